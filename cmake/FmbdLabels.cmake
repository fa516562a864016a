# fmbd_label_tests_at_end(): once the current directory's CMakeLists.txt is processed, gives each
# of its ctest tests its labels, after its name, so that
#   ctest -L graded    the graded tests of the modules (reference, skeleton, source check, sync)
#   ctest -L mutant    the mistake catalogue: each mutant is caught
#   ctest -L M03       everything of module 3 (graded, mutants, demos)
#   ctest -L project   whole-workbook checks (releases, grading routes, physics programs)
# and likewise tools, driver, demo and extras. A test whose name fits no kind gets the label
# "unlabelled"; project.labels refuses that label and tests without any (a directory that adds
# tests without calling this).
function(fmbd_label_tests_at_end)
  get_property(deferred DIRECTORY PROPERTY FMBD_LABELS_DEFERRED)
  if(NOT deferred)
    set_property(DIRECTORY PROPERTY FMBD_LABELS_DEFERRED ON)
    cmake_language(DEFER CALL fmbd_label_tests)
  endif()
endfunction()

function(fmbd_label_tests)
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach(test IN LISTS tests)
    set(labels "")
    if(test MATCHES "^m([0-9][0-9])[.]mutant_caught[.]")
      set(labels "mutant;M${CMAKE_MATCH_1}")
    elseif(test MATCHES "^m([0-9][0-9])[.]")
      set(labels "graded;M${CMAKE_MATCH_1}")
    elseif(test MATCHES "^demo[.]")
      set(labels "demo")
      if(CMAKE_CURRENT_SOURCE_DIR MATCHES "/module([0-9][0-9])_[^/]*/")
        list(APPEND labels "M${CMAKE_MATCH_1}")
      endif()
    elseif(test MATCHES "^(project|tools|driver|extras)[.]")
      set(labels "${CMAKE_MATCH_1}")
    else()
      set(labels "unlabelled")
    endif()
    set_property(TEST "${test}" APPEND PROPERTY LABELS ${labels})
  endforeach()
endfunction()

# Configure-time access to the header of a mistake-catalogue mutant.
#
#   fmbd_read_mutant(MUTANT_FILE OUT_FILE_VAR OUT_EXPECT_VAR)
#       Sets OUT_FILE_VAR to the `file:` field (exercise file, relative to the
#       module's solutions folder) and OUT_EXPECT_VAR to the `expect:` field (the
#       plain phrase the graded tests print when they catch the mutant). Editing
#       the mutant re-runs CMake. Only the header is read here; fmbd-mutate
#       validates the whole file at build time and reads the fields the same way.
#
#   fmbd_regex_escape(OUT_VAR TEXT)
#       Escapes TEXT for use as a literal in a CMake regular expression, e.g. in
#       PASS_REGULAR_EXPRESSION (an `expect:` phrase may contain * . + ? and the like).

include_guard(GLOBAL)

function(fmbd_read_mutant MUTANT_FILE OUT_FILE_VAR OUT_EXPECT_VAR)
  get_filename_component(mutant "${MUTANT_FILE}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  if(NOT EXISTS "${mutant}")
    message(FATAL_ERROR "fmbd_read_mutant: no such mutant file: ${mutant}")
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${mutant}")

  # Header lines only: stop at the first directive, so code in a find or replace
  # block is never mistaken for a field.
  file(STRINGS "${mutant}" lines REGEX "^[ \t]*(file:|expect:|@@)")
  set(file_value "")
  set(expect_value "")
  set(file_seen FALSE)
  set(expect_seen FALSE)
  foreach(line IN LISTS lines)
    if(line MATCHES "^[ \t]*@@")
      break()
    elseif(line MATCHES "^[ \t]*(file|expect):(.*)$")
      set(key "${CMAKE_MATCH_1}")
      string(STRIP "${CMAKE_MATCH_2}" value)
      if(${key}_seen)
        message(FATAL_ERROR "fmbd_read_mutant: ${mutant}: duplicate '${key}:' field")
      endif()
      set(${key}_seen TRUE)
      set(${key}_value "${value}")
    endif()
  endforeach()
  foreach(key IN ITEMS file expect)
    if("${${key}_value}" STREQUAL "")
      message(FATAL_ERROR "fmbd_read_mutant: ${mutant}: missing or empty '${key}:' field")
    endif()
  endforeach()
  set(${OUT_FILE_VAR} "${file_value}" PARENT_SCOPE)
  set(${OUT_EXPECT_VAR} "${expect_value}" PARENT_SCOPE)
endfunction()

function(fmbd_regex_escape OUT_VAR TEXT)
  string(REGEX REPLACE "([][.*+?^$()|\\\\])" "\\\\\\1" escaped "${TEXT}")
  set(${OUT_VAR} "${escaped}" PARENT_SCOPE)
endfunction()

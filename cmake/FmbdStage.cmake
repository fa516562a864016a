# Stage libraries.
#
# fmbd_add_stage(NUMBER 01 DIR module01_kinematics
#                GIVEN src/model_given.cpp ...  # given code, in the module folder only
#                EXERCISES joints.cpp ...)      # exercise files: moduleNN/src and solutions/moduleNN
#
# creates
#   stageNN_headers    interface: include/ of this module and of every earlier one, Eigen
#   stageNN_given      object library of the given files (if any)
#   stageNN_student    static library: given + moduleNN/src/<exercise files>
#   stageNN_reference  static library: given + solutions/moduleNN/<exercise files> (where
#                      solutions/ holds this module and every earlier one: fmbd_has_reference)
#   stageNN_ref_<stem> one object library per reference exercise file (the mutants reuse them)
#
# Capabilities beyond the course live in extras/ (extras/CMakeLists.txt), outside every stage.
#
# A stage library holds only its own symbols; fmbd_link_stages() adds the earlier ones.

set_property(GLOBAL PROPERTY FMBD_STAGES "")

function(fmbd_add_stage)
  cmake_parse_arguments(S "" "NUMBER;DIR" "GIVEN;EXERCISES" ${ARGN})
  set(n ${S_NUMBER})
  set(dir "${PROJECT_SOURCE_DIR}/${S_DIR}")
  get_property(earlier GLOBAL PROPERTY FMBD_STAGES)

  add_library(stage${n}_headers INTERFACE)
  target_include_directories(stage${n}_headers INTERFACE "$<BUILD_INTERFACE:${dir}/include>")
  target_link_libraries(stage${n}_headers INTERFACE Eigen3::Eigen)
  foreach(k IN LISTS earlier)
    target_link_libraries(stage${n}_headers INTERFACE stage${k}_headers)
  endforeach()

  set(given_objects "")
  if(S_GIVEN)
    list(TRANSFORM S_GIVEN PREPEND "${dir}/")
    add_library(stage${n}_given OBJECT ${S_GIVEN})
    target_link_libraries(stage${n}_given PUBLIC stage${n}_headers)
    # Line tables only (-g1): backtraces and breakpoints by line still work, and the Eigen-heavy
    # given files compile in two thirds of the time. The exercise files keep full -g.
    target_compile_options(stage${n}_given PRIVATE "$<$<CONFIG:RelWithDebInfo>:-g1>")
    set(given_objects $<TARGET_OBJECTS:stage${n}_given>)
  endif()

  set(student_sources ${S_EXERCISES})
  list(TRANSFORM student_sources PREPEND "${dir}/src/")
  add_library(stage${n}_student STATIC ${student_sources} ${given_objects})
  target_link_libraries(stage${n}_student PUBLIC stage${n}_headers)
  # A function that forgets its return is an error: it would otherwise crash the tests with
  # SIGABRT or worse. (Stubs mark their parameters with fmbd::unused(), so an unused parameter
  # warns only in a function the student wrote.)
  target_compile_options(stage${n}_student PRIVATE -Werror=return-type)
  if(NOT BUILD_TESTING)
    # The engine only (BUILD_TESTING=OFF): the student variant is built only when asked for, and
    # the given code where the reference links it.
    set_target_properties(stage${n}_student PROPERTIES EXCLUDE_FROM_ALL ON)
    if(S_GIVEN)
      set_target_properties(stage${n}_given PROPERTIES EXCLUDE_FROM_ALL ON)
    endif()
  endif()

  set(has_reference OFF)
  if(EXISTS "${PROJECT_SOURCE_DIR}/solutions/${S_DIR}")
    set(has_reference ON)
    foreach(k IN LISTS earlier)
      get_property(earlier_reference GLOBAL PROPERTY FMBD_STAGE_${k}_REFERENCE)
      if(NOT earlier_reference)
        set(has_reference OFF)
      endif()
    endforeach()
  endif()
  set_property(GLOBAL PROPERTY FMBD_STAGE_${n}_REFERENCE ${has_reference})
  if(has_reference)
    set(reference_objects "")
    foreach(file IN LISTS S_EXERCISES)
      get_filename_component(stem "${file}" NAME_WE)
      add_library(stage${n}_ref_${stem} OBJECT "${PROJECT_SOURCE_DIR}/solutions/${S_DIR}/${file}")
      target_link_libraries(stage${n}_ref_${stem} PUBLIC stage${n}_headers)
      list(APPEND reference_objects $<TARGET_OBJECTS:stage${n}_ref_${stem}>)
    endforeach()
    add_library(stage${n}_reference STATIC ${reference_objects} ${given_objects})
    target_link_libraries(stage${n}_reference PUBLIC stage${n}_headers)
  endif()

  list(APPEND earlier ${n})
  set_property(GLOBAL PROPERTY FMBD_STAGES "${earlier}")
  set_property(GLOBAL PROPERTY FMBD_STAGE_${n}_DIR "${S_DIR}")
  set_property(GLOBAL PROPERTY FMBD_STAGE_${n}_EXERCISES "${S_EXERCISES}")
  set_property(GLOBAL PROPERTY FMBD_STAGE_${n}_HAS_GIVEN "${S_GIVEN}")
endfunction()

# add_subdirectory of a module folder, if this copy has it (a release may stop early).
macro(fmbd_add_module dir)
  if(EXISTS "${PROJECT_SOURCE_DIR}/${dir}/CMakeLists.txt")
    add_subdirectory(${dir})
  endif()
endmacro()

# fmbd_has_reference(<out> <n>): whether stage n (and so every earlier one) has a reference.
function(fmbd_has_reference out n)
  get_property(has GLOBAL PROPERTY FMBD_STAGE_${n}_REFERENCE)
  if(has)
    set(${out} ON PARENT_SCOPE)
  else()
    set(${out} OFF PARENT_SCOPE)
  endif()
endfunction()

# Says at configure time which code the earlier stages use. With FMBD_EARLIER_STAGES=reference, a
# stage whose reference has not been released falls back to the student's own code: a warning
# names those stages, so that nobody believes they are grading on the reference when they are not.
function(fmbd_report_earlier_stages)
  if(NOT FMBD_EARLIER_STAGES STREQUAL "reference")
    return()
  endif()
  get_property(stages GLOBAL PROPERTY FMBD_STAGES)
  set(with)
  set(without)
  foreach(k IN LISTS stages)
    fmbd_has_reference(has ${k})
    if(has)
      list(APPEND with ${k})
    else()
      list(APPEND without ${k})
    endif()
  endforeach()
  if(without)
    list(JOIN with ", " with_text)
    list(JOIN without ", " without_text)
    if(NOT with)
      set(with_text "none")
    endif()
    message(WARNING "fmbd: FMBD_EARLIER_STAGES=reference, but modules ${without_text} have no released "
                    "reference (solutions/): as earlier stages they use your own code. With a reference: "
                    "${with_text}.")
  endif()
endfunction()

# Link stage N in `variant` (student | reference | any static library target)
# and stages 1..N-1 in `earlier_variant` (student | reference; the student variant where a
# stage has no reference).
function(fmbd_link_stages target n variant earlier_variant)
  if(TARGET ${variant})
    set(libs ${variant})
  else()
    set(libs stage${n}_${variant})
  endif()
  get_property(stages GLOBAL PROPERTY FMBD_STAGES)
  list(REVERSE stages)
  foreach(k IN LISTS stages)
    if(k LESS n)
      fmbd_has_reference(has ${k})
      if(earlier_variant STREQUAL "reference" AND has)
        list(APPEND libs stage${k}_reference)
      else()
        list(APPEND libs stage${k}_student)
      endif()
    endif()
  endforeach()
  target_link_libraries(${target} PRIVATE ${libs})
endfunction()

# fmbd_engine: the reference stages 1..8 in link order with the headers of every module, the
# engine that the extras and the installed package build on. It exists where every stage has a
# reference.
function(fmbd_add_engine)
  get_property(stages GLOBAL PROPERTY FMBD_STAGES)
  list(GET stages -1 last)
  fmbd_has_reference(has ${last})
  if(NOT last STREQUAL "08" OR NOT has)
    return()
  endif()
  add_library(fmbd_engine INTERFACE)
  add_library(fmbd::fmbd ALIAS fmbd_engine)
  target_include_directories(fmbd_engine INTERFACE "$<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>")
  target_link_libraries(fmbd_engine INTERFACE stage${last}_headers)
  list(REVERSE stages)
  foreach(k IN LISTS stages)
    target_link_libraries(fmbd_engine INTERFACE stage${k}_reference)
  endforeach()
endfunction()

# Target `studentify`: regenerate every moduleNN_*/src exercise file from solutions/.
function(fmbd_add_studentify_target)
  if(NOT FMBD_INSTRUCTOR_COPY OR NOT FMBD_HAVE_SOLUTIONS)
    return()  # in a student release it would overwrite the student's work
  endif()
  set(commands "")
  get_property(stages GLOBAL PROPERTY FMBD_STAGES)
  foreach(n IN LISTS stages)
    get_property(dir GLOBAL PROPERTY FMBD_STAGE_${n}_DIR)
    get_property(exercises GLOBAL PROPERTY FMBD_STAGE_${n}_EXERCISES)
    foreach(file IN LISTS exercises)
      list(APPEND commands COMMAND fmbd-studentify --source-name solutions/${dir}/${file}
           "${PROJECT_SOURCE_DIR}/solutions/${dir}/${file}" "${PROJECT_SOURCE_DIR}/${dir}/src/${file}")
    endforeach()
  endforeach()
  add_custom_target(studentify ${commands} COMMENT "Regenerating the exercise files from solutions/" VERBATIM)
endfunction()

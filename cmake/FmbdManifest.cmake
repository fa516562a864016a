# The course manifest: <build>/course.json, written at every configure (fmbd_write_manifest(), at
# the end of the top-level CMakeLists.txt) and read by the front end (frontend/manifest.hpp). It
# says what this build has: the modules, the graded programs, the demos and the benchmarks.
#
# Schema 1 (a field's absence is an error unless it says "or null"):
#   {
#     "schema": 1,
#     "source_dir": "/abs/path/of/the/tree",          the folder CMake configured
#     "build_dir": "/abs/path/of/the/build",
#     "grade_driver": "/abs/.../fmbd-grade",          the grade driver, or null (BUILD_TESTING=OFF)
#     "modules": [                                     one per module folder of this build, in order
#       { "number": 1, "id": "M01", "folder": "module01_kinematics",
#         "exercises": ["module01_kinematics/src/planar.cpp", ...],   relative to source_dir
#         "inputs": ["module01_kinematics/answers.txt"],  the student's other files (the answers of
#                                      the tutorial problems, where the module has them)
#         "given": ["module01_kinematics/src/model_given.cpp", ...],
#         "solutions": ["solutions/module01_kinematics/planar.cpp", ...],  those this copy has
#         "tasks": ["M01T1", ...],     the TASK(MnnTk) markers of solutions/ (where this copy has
#                                      them; else the TODO(MnnTk) markers of the exercise files),
#                                      in file order, each once
#         "hints": "module01_kinematics/hints.md",   or null when the module has none
#         "has_reference": true,                     the reference variant of the stage exists
#         "student_library": "/abs/.../libstage01_student.a",  the stage's libraries (the
#         "reference_library": "/abs/.../libfmbd_stage01.a" }  reference's null without one)
#     ],
#     "graded": [                                      one per graded program
#       { "id": "M01", "kind": "catch",                a Catch program speaking the driver's
#                                                      list/token protocol (catch_main.cpp)
#         "module": 1, "program": "/abs/.../m01_student", "target": "m01_student",
#         "reference_program": "/abs/.../m01_reference", "reference_target": "m01_reference",
#                                                      both null without a reference
#         "vet_target": "m01_vet",                     the source check of the program's code, or
#                                                      null (nothing of the student's compiled in)
#         "points": "listed",                          the program lists its tests and points
#         "tags": ["code"] }
#     ],
#     "demos": [ { "name": "spinning_beam", "target": "demo_spinning_beam", "program": "/abs/..." } ],
#     "benchmarks": [ { "name": "simulate", "target": "fmbd-bench-simulate", "program": "/abs/..." } ]
#   }
# graded, demos and benchmarks are empty arrays where the build has none (BUILD_TESTING=OFF, no
# gnuplot-iostream, no extras). Programs are written through $<TARGET_FILE:...> (file(GENERATE)),
# so a build folder whose path holds a '"' or a '\' is not supported.
#
# What it reads, recorded where the lists are made: FMBD_STAGES and FMBD_STAGE_NN_* (FmbdStage.cmake),
# FMBD_GRADED_ITEMS (fmbd_add_graded_item(), autograder/CMakeLists.txt), FMBD_DEMOS
# (FmbdDemo.cmake), FMBD_BENCHMARK_NAMES (extras/CMakeLists.txt).

# fmbd_json_quote(<out> <text>): `text` as a JSON string literal.
function(fmbd_json_quote out text)
  string(REPLACE "\\" "\\\\" text "${text}")
  string(REPLACE "\"" "\\\"" text "${text}")
  string(REPLACE "\n" "\\n" text "${text}")
  string(REPLACE "\r" "\\r" text "${text}")
  string(REPLACE "\t" "\\t" text "${text}")
  set(${out} "\"${text}\"" PARENT_SCOPE)
endfunction()

# fmbd_json_strings(<out> <item>...): a JSON array of strings.
function(fmbd_json_strings out)
  set(items "")
  foreach(item IN LISTS ARGN)
    fmbd_json_quote(quoted "${item}")
    list(APPEND items "${quoted}")
  endforeach()
  list(JOIN items ", " joined)
  set(${out} "[${joined}]" PARENT_SCOPE)
endfunction()

# fmbd_json_objects(<out> <object>...): a JSON array of JSON texts.
function(fmbd_json_objects out)
  list(JOIN ARGN ", " joined)
  set(${out} "[${joined}]" PARENT_SCOPE)
endfunction()

# fmbd_json_object(<out> <key> <json> ...): an object of the key and JSON text pairs, in order.
function(fmbd_json_object out)
  set(object "{}")
  while(ARGN)
    list(POP_FRONT ARGN key value)
    string(JSON object SET "${object}" "${key}" "${value}")
  endwhile()
  set(${out} "${object}" PARENT_SCOPE)
endfunction()

# fmbd_module_tasks(<out> <file>...): the task ids of the markers TASK(MnnTk) or TODO(MnnTk) in
# the files, in order, each once.
function(fmbd_module_tasks out)
  set(tasks "")
  foreach(file IN LISTS ARGN)
    file(STRINGS "${file}" lines REGEX "(TASK|TODO)\\(M[0-9][0-9]T[0-9]+\\)")
    foreach(line IN LISTS lines)
      string(REGEX MATCHALL "(TASK|TODO)\\(M[0-9][0-9]T[0-9]+\\)" markers "${line}")
      foreach(marker IN LISTS markers)
        string(REGEX REPLACE "^[A-Z]+\\((.*)\\)$" "\\1" task "${marker}")
        list(APPEND tasks "${task}")
      endforeach()
    endforeach()
  endforeach()
  list(REMOVE_DUPLICATES tasks)
  set(${out} "${tasks}" PARENT_SCOPE)
endfunction()

# fmbd_program_entries(<out> <prefix> <name>...): {name, target, program} per name, the target
# being <prefix><name>.
function(fmbd_program_entries out prefix)
  set(entries "")
  foreach(name IN LISTS ARGN)
    fmbd_json_quote(name_json "${name}")
    fmbd_json_quote(target_json "${prefix}${name}")
    fmbd_json_quote(program_json "$<TARGET_FILE:${prefix}${name}>")
    fmbd_json_object(entry name "${name_json}" target "${target_json}" program "${program_json}")
    list(APPEND entries "${entry}")
  endforeach()
  fmbd_json_objects(array ${entries})
  set(${out} "${array}" PARENT_SCOPE)
endfunction()

# fmbd_add_graded_item(ID <id> KIND <kind> MODULE <n> TARGET <target> [REFERENCE_TARGET <target>]
#                      [VET_TARGET <target>] [POINTS <how>] [TAGS <tag>...])
# A graded item of the manifest: the program of TARGET, which speaks the grade driver's list/token
# protocol (autograder/driver/grade.cpp). KIND names what it grades ("catch": a Catch program of
# the student's code); the front end treats every kind alike. REFERENCE_TARGET lists the tests
# in place of the student's build; VET_TARGET is the source check of the code it links (none:
# nothing of the student's is compiled into it). POINTS: "listed" (the default).
function(fmbd_add_graded_item)
  cmake_parse_arguments(G "" "ID;KIND;MODULE;TARGET;REFERENCE_TARGET;VET_TARGET;POINTS" "TAGS" ${ARGN})
  if(NOT G_POINTS)
    set(G_POINTS listed)
  endif()
  string(REGEX REPLACE "^0+([0-9])" "\\1" number "${G_MODULE}")
  fmbd_json_quote(id "${G_ID}")
  fmbd_json_quote(kind "${G_KIND}")
  fmbd_json_quote(program "$<TARGET_FILE:${G_TARGET}>")
  fmbd_json_quote(target "${G_TARGET}")
  fmbd_json_quote(points "${G_POINTS}")
  fmbd_json_strings(tags ${G_TAGS})
  set(reference_program null)
  set(reference_target null)
  if(G_REFERENCE_TARGET)
    fmbd_json_quote(reference_program "$<TARGET_FILE:${G_REFERENCE_TARGET}>")
    fmbd_json_quote(reference_target "${G_REFERENCE_TARGET}")
  endif()
  set(vet null)
  if(G_VET_TARGET)
    fmbd_json_quote(vet "${G_VET_TARGET}")
  endif()
  fmbd_json_object(item id "${id}" kind "${kind}" module ${number} program "${program}" target "${target}"
                   reference_program "${reference_program}" reference_target "${reference_target}"
                   vet_target "${vet}" points "${points}" tags "${tags}")
  set_property(GLOBAL APPEND PROPERTY FMBD_GRADED_ITEMS "${item}")
endfunction()

function(fmbd_write_manifest)
  set(src "${PROJECT_SOURCE_DIR}")

  set(modules "")
  get_property(stages GLOBAL PROPERTY FMBD_STAGES)
  foreach(n IN LISTS stages)
    get_property(dir GLOBAL PROPERTY FMBD_STAGE_${n}_DIR)
    get_property(exercises GLOBAL PROPERTY FMBD_STAGE_${n}_EXERCISES)
    get_property(given GLOBAL PROPERTY FMBD_STAGE_${n}_HAS_GIVEN)
    fmbd_has_reference(has_reference ${n})
    string(REGEX REPLACE "^0+([0-9])" "\\1" number "${n}")
    set(exercise_paths "")
    set(solution_paths "")
    set(marked "")
    foreach(file IN LISTS exercises)
      list(APPEND exercise_paths "${dir}/src/${file}")
      if(EXISTS "${src}/solutions/${dir}/${file}")
        list(APPEND solution_paths "solutions/${dir}/${file}")
        list(APPEND marked "${src}/solutions/${dir}/${file}")
      elseif(EXISTS "${src}/${dir}/src/${file}")
        list(APPEND marked "${src}/${dir}/src/${file}")
      endif()
    endforeach()
    set(given_paths "")
    foreach(file IN LISTS given)  # absolute (FmbdStage.cmake), or relative to the module folder
      if(NOT IS_ABSOLUTE "${file}")
        set(file "${src}/${dir}/${file}")
      endif()
      file(RELATIVE_PATH file "${src}" "${file}")
      list(APPEND given_paths "${file}")
    endforeach()
    fmbd_module_tasks(tasks ${marked})
    set(hints null)
    if(EXISTS "${src}/${dir}/hints.md")
      fmbd_json_quote(hints "${dir}/hints.md")
    endif()
    if(has_reference)
      set(has_reference true)
    else()
      set(has_reference false)
    endif()
    fmbd_json_quote(id "M${n}")
    fmbd_json_quote(folder "${dir}")
    fmbd_json_strings(exercise_paths ${exercise_paths})
    fmbd_json_strings(given ${given_paths})
    fmbd_json_strings(solution_paths ${solution_paths})
    fmbd_json_strings(tasks ${tasks})
    fmbd_json_quote(student_library "$<TARGET_FILE:stage${n}_student>")
    set(reference_library null)
    if(has_reference)
      fmbd_json_quote(reference_library "$<TARGET_FILE:stage${n}_reference>")
    endif()
    set(input_paths "")
    if(EXISTS "${src}/${dir}/problems/problems.cpp")  # tutorial problems: their answers file
      list(APPEND input_paths "${dir}/answers.txt")
    endif()
    fmbd_json_strings(inputs ${input_paths})
    fmbd_json_object(module number ${number} id "${id}" folder "${folder}" exercises "${exercise_paths}"
                     inputs "${inputs}"
                     given "${given}" solutions "${solution_paths}" tasks "${tasks}" hints "${hints}"
                     has_reference ${has_reference} student_library "${student_library}"
                     reference_library "${reference_library}")
    list(APPEND modules "${module}")
  endforeach()

  get_property(graded GLOBAL PROPERTY FMBD_GRADED_ITEMS)

  get_property(demos GLOBAL PROPERTY FMBD_DEMOS)
  get_property(benchmarks GLOBAL PROPERTY FMBD_BENCHMARK_NAMES)
  fmbd_program_entries(demos demo_ ${demos})
  fmbd_program_entries(benchmarks fmbd-bench- ${benchmarks})
  fmbd_json_objects(modules ${modules})
  fmbd_json_objects(graded ${graded})
  fmbd_json_quote(source_json "${src}")
  fmbd_json_quote(build_json "${CMAKE_BINARY_DIR}")
  set(driver null)
  if(TARGET fmbd-grade)
    fmbd_json_quote(driver "$<TARGET_FILE:fmbd-grade>")
  endif()
  fmbd_json_object(manifest schema 1 source_dir "${source_json}" build_dir "${build_json}" grade_driver "${driver}"
                   modules "${modules}" graded "${graded}" demos "${demos}" benchmarks "${benchmarks}")
  file(GENERATE OUTPUT "${CMAKE_BINARY_DIR}/course.json" CONTENT "${manifest}\n")
endfunction()

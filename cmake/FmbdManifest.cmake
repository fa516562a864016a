# The course manifest: <build>/course.json, written at every configure (fmbd_write_manifest(), at
# the end of the top-level CMakeLists.txt) and read by the front end. Its schema, with its version
# (kManifestSchema), is documented in one place: frontend/manifest.hpp, beside the reader.
#
# Programs are written through $<TARGET_FILE:...> (file(GENERATE)), so a build folder whose path
# holds a '"' or a '\' is not supported.
#
# What it reads, recorded where the lists are made: FMBD_STAGES and FMBD_STAGE_NN_* (FmbdStage.cmake),
# FMBD_GRADED_ITEMS (fmbd_add_graded_item(), autograder/CMakeLists.txt, problems/CMakeLists.txt),
# FMBD_DEMOS (FmbdDemo.cmake), FMBD_BENCHMARK_NAMES (extras/CMakeLists.txt).

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
#                      [VET_TARGET <target> VET_REPORT <file>] [INPUTS <path>...] [NEEDS_IDENTITY] [LINKS_STUDENT_CODE]
#                      [CLASSROOM] WITHOUT_REFERENCE all|format)
# A graded item of the manifest: the program of TARGET, which speaks the grade driver's list/token
# protocol (autograder/driver/grade.cpp). KIND names what it grades, for people: no code tests it.
# What the front end and the driver do with the item follows from its capabilities, declared here
# (frontend/manifest.hpp has their meaning): INPUTS, the student's files it grades (relative to the
# source tree); NEEDS_IDENTITY, it grades with the numbers of the student's name; LINKS_STUDENT_CODE,
# its program is built from the student's exercise files; CLASSROOM, it is a step of the GitHub
# Classroom workflow; WITHOUT_REFERENCE, what it checks in a copy without its reference (all: every
# test, listed by the student's build; format: the inputs' format only). REFERENCE_TARGET lists the
# tests in place of the student's build; VET_TARGET is the source check of the code it links, which
# writes VET_REPORT (absolute: what it refused, empty when it refused nothing).
function(fmbd_add_graded_item)
  cmake_parse_arguments(G "NEEDS_IDENTITY;LINKS_STUDENT_CODE;CLASSROOM"
                        "ID;KIND;MODULE;TARGET;REFERENCE_TARGET;VET_TARGET;VET_REPORT;WITHOUT_REFERENCE" "INPUTS" ${ARGN})
  if(G_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "fmbd_add_graded_item(${G_ID}): unknown arguments ${G_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT G_WITHOUT_REFERENCE MATCHES "^(all|format)$")
    message(FATAL_ERROR "fmbd_add_graded_item(${G_ID}): WITHOUT_REFERENCE all or format is required")
  endif()
  if((G_VET_TARGET AND NOT G_VET_REPORT) OR (G_VET_REPORT AND NOT G_VET_TARGET))
    message(FATAL_ERROR "fmbd_add_graded_item(${G_ID}): VET_TARGET and VET_REPORT go together")
  endif()
  if(G_VET_TARGET AND NOT G_LINKS_STUDENT_CODE)
    message(FATAL_ERROR "fmbd_add_graded_item(${G_ID}): a VET_TARGET checks student code: add LINKS_STUDENT_CODE")
  endif()
  string(REGEX REPLACE "^0+([0-9])" "\\1" number "${G_MODULE}")
  fmbd_json_quote(id "${G_ID}")
  fmbd_json_quote(kind "${G_KIND}")
  fmbd_json_quote(program "$<TARGET_FILE:${G_TARGET}>")
  fmbd_json_quote(target "${G_TARGET}")
  fmbd_json_strings(inputs ${G_INPUTS})
  fmbd_json_quote(without_reference "${G_WITHOUT_REFERENCE}")
  foreach(flag IN ITEMS NEEDS_IDENTITY LINKS_STUDENT_CODE CLASSROOM)
    if(G_${flag})
      set(${flag} true)
    else()
      set(${flag} false)
    endif()
  endforeach()
  set(reference_program null)
  set(reference_target null)
  if(G_REFERENCE_TARGET)
    fmbd_json_quote(reference_program "$<TARGET_FILE:${G_REFERENCE_TARGET}>")
    fmbd_json_quote(reference_target "${G_REFERENCE_TARGET}")
  endif()
  set(vet null)
  set(vet_report null)
  if(G_VET_TARGET)
    fmbd_json_quote(vet "${G_VET_TARGET}")
    fmbd_json_quote(vet_report "${G_VET_REPORT}")
  endif()
  fmbd_json_object(item id "${id}" kind "${kind}" module ${number} program "${program}" target "${target}"
                   reference_program "${reference_program}" reference_target "${reference_target}"
                   vet_target "${vet}" vet_report "${vet_report}" inputs "${inputs}" needs_identity ${NEEDS_IDENTITY}
                   links_student_code ${LINKS_STUDENT_CODE} classroom ${CLASSROOM}
                   without_reference "${without_reference}")
  set_property(GLOBAL APPEND PROPERTY FMBD_GRADED_ITEMS "${item}")
endfunction()

function(fmbd_write_manifest)
  set(src "${PROJECT_SOURCE_DIR}")

  set(modules "")
  get_property(stages GLOBAL PROPERTY FMBD_STAGES)
  foreach(n IN LISTS stages)
    get_property(dir GLOBAL PROPERTY FMBD_STAGE_${n}_DIR)
    get_property(exercises GLOBAL PROPERTY FMBD_STAGE_${n}_EXERCISES)
    fmbd_has_reference(has_reference ${n})
    string(REGEX REPLACE "^0+([0-9])" "\\1" number "${n}")
    set(exercise_paths "")
    foreach(file IN LISTS exercises)
      list(APPEND exercise_paths "${dir}/src/${file}")
    endforeach()
    set(hints null)
    if(EXISTS "${src}/${dir}/hints.md")
      fmbd_json_quote(hints "${dir}/hints.md")
    endif()
    fmbd_json_quote(id "M${n}")
    fmbd_json_quote(folder "${dir}")
    fmbd_json_strings(exercise_paths ${exercise_paths})
    fmbd_json_quote(student_library "$<TARGET_FILE:stage${n}_student>")
    set(reference_library null)
    if(has_reference)
      fmbd_json_quote(reference_library "$<TARGET_FILE:stage${n}_reference>")
    endif()
    fmbd_json_object(module number ${number} id "${id}" folder "${folder}" exercises "${exercise_paths}"
                     hints "${hints}" student_library "${student_library}"
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
  set(instructor false)
  if(FMBD_INSTRUCTOR_COPY)
    set(instructor true)
  endif()
  set(policy null)
  if(EXISTS "${src}/autograder/release_policy.txt")
    fmbd_json_quote(policy "autograder/release_policy.txt")
  endif()
  fmbd_json_object(manifest schema 3 source_dir "${source_json}" build_dir "${build_json}" grade_driver "${driver}"
                   instructor ${instructor} release_policy "${policy}"
                   modules "${modules}" graded "${graded}" demos "${demos}" benchmarks "${benchmarks}")
  file(GENERATE OUTPUT "${CMAKE_BINARY_DIR}/course.json" CONTENT "${manifest}\n")
endfunction()

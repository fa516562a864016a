# Joins the source check's reports of the stages a graded program links (REPORTS, a list) into
# OUT, with a closing note when there is any finding, and fails then.
#   cmake "-DREPORTS=a.txt;b.txt" -DOUT=mNN.txt -P vet_join.cmake
set(joined "")
foreach(report IN LISTS REPORTS)
  file(READ "${report}" text)
  string(APPEND joined "${text}")
endforeach()
if(joined STREQUAL "")
  file(WRITE "${OUT}" "")
  return()
endif()
string(APPEND joined "The source check refuses what could reach into the grader (files, processes, system calls, "
                     "the test harness); an exercise needs none of it. Allowed headers and functions: "
                     "autograder/vet_allow.txt.\n")
file(WRITE "${OUT}" "${joined}")
message(FATAL_ERROR "the source check refused the exercise files (${OUT})")

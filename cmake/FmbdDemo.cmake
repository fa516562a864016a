# Lecture demos (gnuplot-iostream). Built only when gnuplot-iostream is present.
#
# fmbd_add_demo(NAME slider_crank_kinematics STAGE 02 SOURCE slider_crank_kinematics.cpp)
#   builds executable demo_<NAME> on the reference stages where this copy has them: stage NN and
#   every earlier stage in its reference variant, or, where a release has not released stage
#   NN's reference, the student's stage NN on the reference of every earlier stage released (the
#   student's own code where it is not). With the whole reference it registers the ctest
#   demo.<NAME>.writes_png_and_csv.

set_property(GLOBAL PROPERTY FMBD_DEMOS "")

function(fmbd_add_demo)
  cmake_parse_arguments(D "" "NAME;STAGE;SOURCE" "" ${ARGN})
  if(NOT FMBD_HAVE_DEMOS)
    return()
  endif()
  fmbd_has_reference(has_reference ${D_STAGE})
  set(variant student)
  if(has_reference)
    set(variant reference)
  endif()
  add_executable(demo_${D_NAME} ${D_SOURCE})
  target_link_libraries(demo_${D_NAME} PRIVATE fmbd_demo_support)
  fmbd_link_stages(demo_${D_NAME} ${D_STAGE} ${variant} reference)
  set_property(GLOBAL APPEND PROPERTY FMBD_DEMOS ${D_NAME})
  if(has_reference)
    set(out "${CMAKE_BINARY_DIR}/demo-check/${D_NAME}")
    fmbd_label_tests_at_end()
    add_test(NAME demo.${D_NAME}.writes_png_and_csv
             COMMAND ${CMAKE_COMMAND} -DDEMO=$<TARGET_FILE:demo_${D_NAME}> -DOUT=${out}
                     -P "${PROJECT_SOURCE_DIR}/cmake/check_demo.cmake")
  endif()
endfunction()

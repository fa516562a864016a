# The installable engine: `cmake --install <build> --prefix <dir>` installs the headers of every
# module, the umbrella header fmbd/fmbd.hpp, the reference libraries of the eight stages and of
# the extras that were built, and the CMake package `fmbd`:
#
#   find_package(fmbd 0.1 REQUIRED)                  # fmbd::fmbd, needs Eigen 3.4 only
#   find_package(fmbd 0.1 COMPONENTS implicit)       # fmbd::implicit (and fast_ffrf, fe_import, sparse)
#
# The engine is the reference code (solutions/ of every module): a copy without it installs
# nothing. Spectra, which extras/sparse uses inside its sources only, is not needed to link it.

if(NOT TARGET fmbd_engine)
  return()
endif()

include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(FMBD_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/fmbd")
get_property(stages GLOBAL PROPERTY FMBD_STAGES)
get_property(extras GLOBAL PROPERTY FMBD_EXTRAS)

set(targets fmbd_engine)
foreach(n IN LISTS stages)
  get_property(dir GLOBAL PROPERTY FMBD_STAGE_${n}_DIR)
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/${dir}/include/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
  set_target_properties(stage${n}_reference PROPERTIES EXPORT_NAME stage${n} OUTPUT_NAME fmbd_stage${n})
  set_target_properties(stage${n}_headers PROPERTIES EXPORT_NAME stage${n}_headers)
  list(APPEND targets stage${n}_reference stage${n}_headers)
endforeach()
install(DIRECTORY "${PROJECT_SOURCE_DIR}/include/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
set_target_properties(fmbd_engine PROPERTIES EXPORT_NAME fmbd)
target_include_directories(fmbd_engine INTERFACE "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")

foreach(extra IN LISTS extras)
  if(EXISTS "${PROJECT_SOURCE_DIR}/extras/${extra}/include")
    install(DIRECTORY "${PROJECT_SOURCE_DIR}/extras/${extra}/include/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
  endif()
  set_target_properties(fmbd_${extra} PROPERTIES EXPORT_NAME ${extra})
  list(APPEND targets fmbd_${extra})
endforeach()

install(TARGETS ${targets} EXPORT fmbdTargets
        ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
        INCLUDES DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
install(EXPORT fmbdTargets NAMESPACE fmbd:: DESTINATION "${FMBD_CMAKE_DIR}")

list(JOIN extras " " FMBD_INSTALLED_EXTRAS)
configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/fmbdConfig.cmake.in"
                              "${CMAKE_BINARY_DIR}/fmbdConfig.cmake" INSTALL_DESTINATION "${FMBD_CMAKE_DIR}")
write_basic_package_version_file("${CMAKE_BINARY_DIR}/fmbdConfigVersion.cmake" COMPATIBILITY SameMinorVersion)
install(FILES "${CMAKE_BINARY_DIR}/fmbdConfig.cmake" "${CMAKE_BINARY_DIR}/fmbdConfigVersion.cmake"
        DESTINATION "${FMBD_CMAKE_DIR}")

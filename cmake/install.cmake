# `cmake --install` and the exported package: find_package(cube4) gives
# cube4::cube4_system (the system model and the Accelerator IP block, with
# the RTL variants this build verilated), cube4::cube4_host_if and
# cube4::cube4_golden (with cube4::cube4_stream, which the system links), and the headers under include/cube4/.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(_cube4_exported cube4_golden cube4_stream cube4_host_if cube4_system cube4_nifti)
# The libraries name the source tree as their include directory; installed,
# the headers are under include/cube4. The verilated models' folders, which
# verilate() makes public, are for the library's own sources only (the
# installed headers never include a verilated header).
foreach(_t ${_cube4_exported})
  get_target_property(_inc ${_t} INTERFACE_INCLUDE_DIRECTORIES)
  set(_new "")
  foreach(_d ${_inc})
    if(_d STREQUAL PROJECT_SOURCE_DIR)
      list(APPEND _new "$<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>"
                       "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/cube4>")
    elseif(NOT _d MATCHES "^${PROJECT_BINARY_DIR}/")
      list(APPEND _new "${_d}")
    endif()
  endforeach()
  set_target_properties(${_t} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_new}")
endforeach()

install(TARGETS ${_cube4_exported} EXPORT cube4Targets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(_dir golden systemc)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${_dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/cube4/${_dir}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
set(_cube4_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/cube4)
install(EXPORT cube4Targets NAMESPACE cube4:: DESTINATION ${_cube4_cmake_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/cube4Config.cmake.in
  ${PROJECT_BINARY_DIR}/cube4Config.cmake INSTALL_DESTINATION ${_cube4_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cube4ConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/cube4Config.cmake ${PROJECT_BINARY_DIR}/cube4ConfigVersion.cmake
        DESTINATION ${_cube4_cmake_dir})

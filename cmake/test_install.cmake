# ctest Install.ExampleAgainstTheInstalledPackage: installs this build into a
# scratch prefix, builds examples/platform on its own with find_package(cube4)
# and runs it (exit 0: its frame through the IP block equals golden).
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -P test_install.cmake
file(REMOVE_RECURSE ${WORK_DIR})
foreach(step
    "${CMAKE_COMMAND};--install;${BUILD_DIR};--prefix;${WORK_DIR}/prefix"
    "${CMAKE_COMMAND};-S;${SOURCE_DIR}/examples/platform;-B;${WORK_DIR}/build;-G;Ninja;-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix"
    "${CMAKE_COMMAND};--build;${WORK_DIR}/build"
    "${WORK_DIR}/build/cube4_platform")
  execute_process(COMMAND ${step} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install test: `${step}` failed (${rc}):\n${out}\n${err}")
  endif()
endforeach()
message(STATUS "install test: ${out}")
file(REMOVE_RECURSE ${WORK_DIR})

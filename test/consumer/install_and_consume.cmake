# cmake -P script behind the ctest entry install_and_consume (see CMakeLists.txt next to it).
# Inputs: MAIN_BUILD_DIR, LIBRARY_FILE, BUILD_CONFIG, PREFIX, CONSUMER_SOURCE_DIR,
# CONSUMER_BINARY_DIR, CXX_COMPILER.
cmake_minimum_required(VERSION 3.16)

foreach(var MAIN_BUILD_DIR LIBRARY_FILE PREFIX INCLUDE_SUFFIX CONSUMER_SOURCE_DIR CONSUMER_BINARY_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "install_and_consume.cmake: ${var} is not set")
  endif()
endforeach()
if(NOT EXISTS "${LIBRARY_FILE}")
  message(FATAL_ERROR "install_and_consume: ${LIBRARY_FILE} is not built; run cmake --build first")
endif()
if("${BUILD_CONFIG}" STREQUAL "")
  set(BUILD_CONFIG Release)
endif()

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install_and_consume: ${what} failed (${rc})")
  endif()
endfunction()

# A fresh prefix and consumer build every time, so that nothing stale can make the test pass.
file(REMOVE_RECURSE "${PREFIX}" "${CONSUMER_BINARY_DIR}")

run_step("cmake --install"
  "${CMAKE_COMMAND}" --install "${MAIN_BUILD_DIR}" --prefix "${PREFIX}" --config "${BUILD_CONFIG}")

# The installed layout that consumers rely on.
set(expected
  include/${INCLUDE_SUFFIX}/opencv2/essential.hpp
  include/${INCLUDE_SUFFIX}/opencv2/essential/params.hpp
  include/${INCLUDE_SUFFIX}/opencv2/essential/solver.hpp
  lib/cmake/opencv_essential/opencv_essentialConfig.cmake
  lib/cmake/opencv_essential/opencv_essentialConfigVersion.cmake
  lib/cmake/opencv_essential/opencv_essentialTargets.cmake)
foreach(f ${expected})
  if(NOT EXISTS "${PREFIX}/${f}")
    message(FATAL_ERROR "install_and_consume: ${PREFIX}/${f} was not installed")
  endif()
endforeach()
file(GLOB shared_libs "${PREFIX}/lib/libopencv_essential.so*")
file(GLOB static_libs "${PREFIX}/lib/libopencv_essential.a")
if(NOT shared_libs AND NOT static_libs)
  message(FATAL_ERROR "install_and_consume: no libopencv_essential under ${PREFIX}/lib")
endif()
# Private pieces must stay private: no internal target, no Eigen in the exported interface.
file(GLOB target_files "${PREFIX}/lib/cmake/opencv_essential/*.cmake")
foreach(f ${target_files})
  file(READ "${f}" content)
  if(content MATCHES "opencv_essential_internal|Eigen")
    message(FATAL_ERROR "install_and_consume: ${f} mentions a private dependency")
  endif()
endforeach()

set(configure_args -S "${CONSUMER_SOURCE_DIR}" -B "${CONSUMER_BINARY_DIR}"
    "-DCMAKE_PREFIX_PATH=${PREFIX}" "-DCMAKE_BUILD_TYPE=${BUILD_CONFIG}"
    -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON)
if(CXX_COMPILER)
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()
run_step("configuring the consumer project" "${CMAKE_COMMAND}" ${configure_args})
run_step("building the consumer project"
  "${CMAKE_COMMAND}" --build "${CONSUMER_BINARY_DIR}" --config "${BUILD_CONFIG}")

find_program(consumer_exe NAMES essential_consumer
  PATHS "${CONSUMER_BINARY_DIR}" "${CONSUMER_BINARY_DIR}/${BUILD_CONFIG}" NO_DEFAULT_PATH)
if(NOT consumer_exe)
  message(FATAL_ERROR "install_and_consume: essential_consumer was not built")
endif()
run_step("running the consumer" "${consumer_exe}")
message(STATUS "install_and_consume: passed")

# Installs the build into PREFIX (fresh) and checks that every program of PROGRAMS (a ;-list) is in
# PREFIX/bin and runs from there: `PROGRAM --help` exits with 0 and prints its usage line (so the
# installed program finds the installed library). Arguments: BUILD_DIR, BUILD_CONFIG, PREFIX,
# PROGRAMS. Licensed under the Apache License, Version 2.0.
file(REMOVE_RECURSE "${PREFIX}")
if("${BUILD_CONFIG}" STREQUAL "")
  set(BUILD_CONFIG Release)
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX}
                        --config ${BUILD_CONFIG}
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${code}): ${err}")
endif()
foreach(program IN LISTS PROGRAMS)
  set(path ${PREFIX}/bin/${program})
  if(NOT EXISTS "${path}")
    message(FATAL_ERROR "${path} was not installed")
  endif()
  execute_process(COMMAND ${path} --help RESULT_VARIABLE code OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT code EQUAL 0 OR NOT out MATCHES "usage: ${program}")
    message(FATAL_ERROR "installed ${path} --help: exit ${code}; ${err}")
  endif()
  message(STATUS "installed and runs: ${path}")
endforeach()

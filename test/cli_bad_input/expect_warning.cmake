# Runs a command that must succeed (exit 0) and print a warning line on stderr matching
# EXPECT_REGEX. Arguments: COMMAND (a ;-list), EXPECT_REGEX.
# Licensed under the Apache License, Version 2.0.
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REPLACE ";" " " shown "${COMMAND}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "'${shown}' exited with ${code}; stderr: ${err}")
endif()
if(NOT err MATCHES "${EXPECT_REGEX}")
  message(FATAL_ERROR "stderr of '${shown}' does not match '${EXPECT_REGEX}': ${err}")
endif()
message(STATUS "warning as expected: ${err}")

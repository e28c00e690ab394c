# Runs essential_sequence with --csv CSV and checks that it exits with 0, wrote ROWS data rows,
# and that every row is marked correct. Arguments: COMMAND (a ;-list), CSV, ROWS.
# Licensed under the Apache License, Version 2.0.
file(REMOVE "${CSV}")
execute_process(COMMAND ${COMMAND} --csv ${CSV} RESULT_VARIABLE code OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "essential_sequence exited with ${code}: ${err}")
endif()
message(STATUS "${out}")
file(STRINGS "${CSV}" lines)
list(POP_FRONT lines header)
if(NOT header MATCHES "t_err_deg,r_err_deg,correct$")
  message(FATAL_ERROR "unexpected CSV header: ${header}")
endif()
list(LENGTH lines rows)
if(NOT rows EQUAL ROWS)
  message(FATAL_ERROR "${rows} CSV rows, expected ${ROWS}")
endif()
foreach(line IN LISTS lines)
  if(NOT line MATCHES ",1$")
    message(FATAL_ERROR "a pair is not correct: ${line}")
  endif()
endforeach()

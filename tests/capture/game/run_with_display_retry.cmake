# SPDX-License-Identifier: MIT
# run_with_display_retry(<rc var> <log var> <command>...): execute_process of the command,
# stdout and stderr both into the log, which is printed. xvfb-run -a can lose the race for a
# display number to another xvfb-run starting at the same moment (parallel ctest, other
# tests): that is retried (three attempts in all), nothing else is.
macro(run_with_display_retry rcVar logVar)
  foreach(attempt 1 2 3)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE ${rcVar} OUTPUT_VARIABLE ${logVar} ERROR_VARIABLE ${logVar})
    if(NOT ${logVar} MATCHES "xvfb-run: error|Xvfb failed to start|Server is already active")
      break()
    endif()
    execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1)
  endforeach()
  message(STATUS "${${logVar}}")
endmacro()

# SPDX-License-Identifier: MIT
# Runs racer with ARGS and --capture OUT; fails unless it exits 0 and OUT exists.
file(REMOVE ${OUT})
separate_arguments(args UNIX_COMMAND "${ARGS}")
execute_process(COMMAND ${RACER} ${args} --capture ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "racer exited with ${rc}")
endif()
if(NOT EXISTS ${OUT})
  message(FATAL_ERROR "racer did not write ${OUT}")
endif()

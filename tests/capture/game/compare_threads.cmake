# SPDX-License-Identifier: MIT
# The same capture with --threads 1 and --threads 2 must be byte-identical.
separate_arguments(args UNIX_COMMAND "${ARGS}")
foreach(n 1 2)
  file(REMOVE ${OUT}/threads${n}.png)
  execute_process(COMMAND ${RACER} ${args} --threads ${n} --capture ${OUT}/threads${n}.png RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "racer --threads ${n} exited with ${rc}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/threads1.png ${OUT}/threads2.png RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "captures differ between --threads 1 and --threads 2")
endif()

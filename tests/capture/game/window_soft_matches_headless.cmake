# racer --backend soft in a window (under xvfb-run) and headless, same flags: the captures
# must be byte-identical (the window only shows the soft frame; the simulation steps alike).
separate_arguments(args UNIX_COMMAND "${ARGS}")
file(REMOVE ${OUT}/window_soft.png ${OUT}/headless_soft.png)
foreach(attempt 1 2 3)  # a lost race for a display number (see expect_output.cmake) is retried
  execute_process(COMMAND ${XVFB} -a ${RACER} ${args} --capture ${OUT}/window_soft.png
                  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT log MATCHES "xvfb-run: error|Xvfb failed to start|Server is already active")
    break()
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1)
endforeach()
message(STATUS "${log}")
if(NOT rc EQUAL 0 OR NOT log MATCHES "backend soft.*, window")
  message(FATAL_ERROR "windowed racer exited with ${rc} or did not open a window")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env DISPLAY= ${RACER} --headless ${args} --capture ${OUT}/headless_soft.png
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "headless racer exited with ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/window_soft.png ${OUT}/headless_soft.png RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "the window's soft frame differs from the headless capture")
endif()

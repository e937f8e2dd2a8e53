# SPDX-License-Identifier: MIT
# racer --backend soft in a window (under xvfb-run) and headless, same flags: the captures
# must be byte-identical (the window only shows the soft frame; the simulation steps alike).
include(${CMAKE_CURRENT_LIST_DIR}/run_with_display_retry.cmake)
separate_arguments(args UNIX_COMMAND "${ARGS}")
file(REMOVE ${OUT}/window_soft.png ${OUT}/headless_soft.png)
run_with_display_retry(rc log ${XVFB} -a ${RACER} ${args} --capture ${OUT}/window_soft.png)
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

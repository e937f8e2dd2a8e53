# SPDX-License-Identifier: MIT
# racer --backend soft --camera free in a window (under xvfb-run): unmoved, its capture is
# byte-identical to the headless --camera free capture (the free camera starts at the
# headless overview); with FLY_SCRIPT (keys held, e.g. "0-2:W") the capture differs (the
# flown pose reaches the renderer, not just the printed line).
include(${CMAKE_CURRENT_LIST_DIR}/run_with_display_retry.cmake)
separate_arguments(args UNIX_COMMAND "${ARGS}")
set(still ${OUT}/free_still.png)
set(flown ${OUT}/free_flown.png)
set(headless ${OUT}/free_headless.png)
file(REMOVE ${still} ${flown} ${headless})
function(run_window capture)
  run_with_display_retry(rc log ${XVFB} -a ${RACER} ${args} ${ARGN} --capture ${capture})
  if(NOT rc EQUAL 0 OR NOT log MATCHES "camera free, backend soft.*, window")
    message(FATAL_ERROR "windowed racer ${ARGN} exited with ${rc} or did not open a window")
  endif()
endfunction()
run_window(${still})
run_window(${flown} --script ${FLY_SCRIPT})
execute_process(COMMAND ${CMAKE_COMMAND} -E env DISPLAY= ${RACER} --headless ${args} --capture ${headless}
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "headless racer exited with ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${still} ${headless} RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "the unmoved free camera's window frame differs from the headless --camera free capture")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${flown} ${still} RESULT_VARIABLE same)
if(same EQUAL 0)
  message(FATAL_ERROR "flying (--script ${FLY_SCRIPT}) left the free camera's frame unchanged")
endif()

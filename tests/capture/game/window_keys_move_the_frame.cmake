# SPDX-License-Identifier: MIT
# racer --backend soft in a window (under xvfb-run), once left alone and once with keys held by
# SCRIPT: left alone, its capture is byte-identical to the headless capture of the same flags;
# with the keys, the capture differs (what the keys move reaches the renderer, not just the
# printed line). The free camera's fly keys (unmoved: the headless overview) and the chase
# camera's drive keys (unmoved: the autopilot) are both checked this way.
#   -DRACER=racer -DXVFB=xvfb-run -DOUT=dir -DNAME=name -DARGS="flags of every run, --camera too"
#   -DSCRIPT=keys (e.g. 0-2:W) -DWHAT="what the keys do, for messages"
#   [-DSTILL_LOG=regex -DMOVED_LOG=regex: what each window run must print]
include(${CMAKE_CURRENT_LIST_DIR}/run_with_display_retry.cmake)
separate_arguments(args UNIX_COMMAND "${ARGS}")
set(still ${OUT}/${NAME}_still.png)
set(moved ${OUT}/${NAME}_moved.png)
set(headless ${OUT}/${NAME}_headless.png)
file(REMOVE ${still} ${moved} ${headless})
function(run_window capture expect)
  run_with_display_retry(rc log ${XVFB} -a ${RACER} ${args} ${ARGN} --capture ${capture})
  if(NOT rc EQUAL 0 OR NOT log MATCHES "backend soft.*, window")
    message(FATAL_ERROR "windowed racer ${ARGN} exited with ${rc} or did not open a window")
  endif()
  if(NOT log MATCHES "${expect}")
    message(FATAL_ERROR "windowed racer ${ARGN}: no '${expect}' in its output:\n${log}")
  endif()
endfunction()
run_window(${still} "${STILL_LOG}")
run_window(${moved} "${MOVED_LOG}" --script ${SCRIPT})
execute_process(COMMAND ${CMAKE_COMMAND} -E env DISPLAY= ${RACER} --headless ${args} --capture ${headless}
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "headless racer exited with ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${still} ${headless} RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "the window's frame without keys differs from the headless capture (${ARGS})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${moved} ${still} RESULT_VARIABLE same)
if(same EQUAL 0)
  message(FATAL_ERROR "${WHAT} (--script ${SCRIPT}) left the frame unchanged")
endif()

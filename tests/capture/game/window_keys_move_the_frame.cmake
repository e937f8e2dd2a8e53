# SPDX-License-Identifier: MIT
# racer --backend soft in a window (under xvfb-run), once left alone and once with keys held by
# SCRIPT: left alone, its capture is byte-identical to the headless capture of the same flags;
# with the keys, the capture differs (what the keys move reaches the renderer, not just the
# printed line). The free camera's fly keys (unmoved: the headless overview) and the chase
# camera's drive keys (unmoved: the autopilot) are both checked this way.
#   -DRACER=racer -DXVFB=xvfb-run -DOUT=dir -DNAME=name -DARGS="flags of every run, --camera too"
#   -DSCRIPT=keys (e.g. 0-2:W) -DWHAT="what the keys do, for messages"
#   [-DSTILL_LOG=regex -DMOVED_LOG=regex: what each window run must print]
include(${CMAKE_CURRENT_LIST_DIR}/racer_runs.cmake)
separate_arguments(args UNIX_COMMAND "${ARGS}")
set(still ${OUT}/${NAME}_still.png)
set(moved ${OUT}/${NAME}_moved.png)
set(headless ${OUT}/${NAME}_headless.png)
file(REMOVE ${still} ${moved} ${headless})
racer_window_capture(${still} "backend soft.*, window" "${STILL_LOG}")
racer_window_capture(${moved} "backend soft.*, window" "${MOVED_LOG}" --script ${SCRIPT})
racer_headless_capture(${headless})
expect_same_file(${still} ${headless} "the window's frame without keys differs from the headless capture (${ARGS})")
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${moved} ${still} RESULT_VARIABLE same)
if(same EQUAL 0)
  message(FATAL_ERROR "${WHAT} (--script ${SCRIPT}) left the frame unchanged")
endif()

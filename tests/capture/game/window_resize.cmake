# SPDX-License-Identifier: MIT
# racer in a window (under xvfb-run) that its --script resizes, against a headless run of the
# same flags at the new size: the window's frames after the resize are rendered at the new
# size (its log says so and its capture has that size) and show what the headless run
# captures -- byte for byte, or with IDIFF within FAIL / FAILPERCENT (a GL window's and a
# headless EGL context's driver may round differently; llvmpipe here does not).
#   -DRACER=racer -DXVFB=xvfb-run -DOUT=dir -DNAME=name -DARGS="flags of both runs"
#   -DFIRST=WxH (the window's --size) -DSCRIPT=--script -DSIZE=WxH (after the resize)
#   [-DIDIFF=ssam-idiff -DFAIL=0.1 -DFAILPERCENT=0.05]
include(${CMAKE_CURRENT_LIST_DIR}/run_with_display_retry.cmake)
separate_arguments(args UNIX_COMMAND "${ARGS}")
set(window ${OUT}/${NAME}_window.png)
set(headless ${OUT}/${NAME}_headless.png)
file(REMOVE ${window} ${headless})
run_with_display_retry(rc log ${XVFB} -a ${RACER} ${args} --size ${FIRST} --script ${SCRIPT} --capture ${window})
if(NOT rc EQUAL 0 OR NOT log MATCHES ", ${FIRST}, .*, window")
  message(FATAL_ERROR "windowed racer exited with ${rc} or did not open a window")
endif()
if(NOT log MATCHES "racer: render size ${SIZE} \\(window framebuffer ${SIZE}\\).*, last at ${SIZE}")
  message(FATAL_ERROR "the window's frames were not rendered at ${SIZE} after --script ${SCRIPT}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env DISPLAY= ${RACER} --headless ${args} --size ${SIZE} --capture ${headless}
                RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "headless racer exited with ${rc}:\n${log}")
endif()
if(DEFINED IDIFF)
  execute_process(COMMAND ${IDIFF} ${window} ${headless} --fail ${FAIL} --warn ${FAIL} --failpercent ${FAILPERCENT}
                          --warnpercent ${FAILPERCENT}
                  RESULT_VARIABLE same OUTPUT_VARIABLE report ERROR_VARIABLE report)
  message(STATUS "${report}")
else()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${window} ${headless} RESULT_VARIABLE same)
endif()
if(NOT same EQUAL 0)
  message(FATAL_ERROR "the window's frame at ${SIZE} differs from the headless ${SIZE} capture")
endif()

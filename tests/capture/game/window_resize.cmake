# SPDX-License-Identifier: MIT
# racer in a window (under xvfb-run) that its --script resizes, against a headless run of the
# same flags at the new size: the window's frames after the resize are rendered at the new
# size (its log says so and its capture has that size) and show what the headless run
# captures -- byte for byte, or with IDIFF within FAIL / FAILPERCENT (a GL window's and a
# headless EGL context's driver may round differently; llvmpipe here does not).
#   -DRACER=racer -DXVFB=xvfb-run -DOUT=dir -DNAME=name -DARGS="flags of both runs"
#   -DFIRST=WxH (the window's --size) -DSCRIPT=--script -DSIZE=WxH (after the resize)
#   [-DIDIFF=ssam-idiff -DFAIL=0.1 -DFAILPERCENT=0.05] [-DEXPECT_TOO=regex the window's log also matches]
include(${CMAKE_CURRENT_LIST_DIR}/racer_runs.cmake)
separate_arguments(args UNIX_COMMAND "${ARGS}")
set(window ${OUT}/${NAME}_window.png)
set(headless ${OUT}/${NAME}_headless.png)
file(REMOVE ${window} ${headless})
# Rendered at the new size after the resize: the log says so.
set(expected "racer: render size ${SIZE} \\(window framebuffer ${SIZE}\\).*, last at ${SIZE}")
if(DEFINED EXPECT_TOO)
  string(APPEND expected ".*${EXPECT_TOO}")
endif()
racer_window_capture(${window} ", ${FIRST}, .*, window" "${expected}"
                     --size ${FIRST} --script ${SCRIPT})
racer_headless_capture(${headless} --size ${SIZE})
set(differs "the window's frame at ${SIZE} differs from the headless ${SIZE} capture")
if(DEFINED IDIFF)
  execute_process(COMMAND ${IDIFF} ${window} ${headless} --fail ${FAIL} --warn ${FAIL} --failpercent ${FAILPERCENT}
                          --warnpercent ${FAILPERCENT}
                  RESULT_VARIABLE same OUTPUT_VARIABLE report ERROR_VARIABLE report)
  message(STATUS "${report}")
  if(NOT same EQUAL 0)
    message(FATAL_ERROR "${differs}")
  endif()
else()
  expect_same_file(${window} ${headless} "${differs}")
endif()

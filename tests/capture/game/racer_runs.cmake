# SPDX-License-Identifier: MIT
# The racer runs the window scripts make (RACER, XVFB and args set by the includer):
# racer_window_capture(<capture> <opened> <expected> [flags...]): racer under xvfb-run (retried
# as run_with_display_retry does) with the args and flags, capturing to <capture>; fails the
# test unless it exits 0 and its output matches <opened> (a window was opened) and <expected>.
# racer_headless_capture(<capture> [flags...]): racer --headless with no display, the script's
# args and the flags, capturing to <capture>; fails the test with racer's output if it fails.
# expect_same_file(<a> <b> <message>): fails the test with the message unless the bytes match.
include(${CMAKE_CURRENT_LIST_DIR}/run_with_display_retry.cmake)

function(racer_window_capture capture opened expected)
  run_with_display_retry(rc log ${XVFB} -a ${RACER} ${args} ${ARGN} --capture ${capture})
  if(NOT rc EQUAL 0 OR NOT log MATCHES "${opened}")
    message(FATAL_ERROR "windowed racer ${ARGN} exited with ${rc} or did not open a window")
  endif()
  if(NOT log MATCHES "${expected}")
    message(FATAL_ERROR "windowed racer ${ARGN}: no '${expected}' in its output:\n${log}")
  endif()
endfunction()

function(racer_headless_capture capture)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env DISPLAY= ${RACER} --headless ${args} ${ARGN} --capture ${capture}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "headless racer exited with ${rc}:\n${log}")
  endif()
endfunction()

function(expect_same_file a b message)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${a} ${b} RESULT_VARIABLE same)
  if(NOT same EQUAL 0)
    message(FATAL_ERROR "${message}")
  endif()
endfunction()

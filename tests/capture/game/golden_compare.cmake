# SPDX-License-Identifier: MIT
# Renders one racer capture and compares it with its golden the way idiff does (ssam-idiff).
#   -DRACER=racer -DIDIFF=ssam-idiff -DARGS="racer flags" -DOUT=out.png -DGOLDEN=golden.png
#   -DFAIL=<per-value threshold> -DFAILPERCENT=<% of pixels allowed over it> [-DHARDFAIL=<max error>]
# On failure the difference |out - golden| * 8 is written next to the output (OUT.diff.png).
# With SSAM_UPDATE_GOLDENS=1 in the environment the capture becomes the golden instead
# (only soft-backend tests do that: goldens always come from the deterministic backend).
separate_arguments(args UNIX_COMMAND "${ARGS}")
file(REMOVE ${OUT})
execute_process(COMMAND ${RACER} ${args} --capture ${OUT} RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT})
  message(FATAL_ERROR "racer ${ARGS} exited with ${rc} (capture written: ${OUT}):\n${log}")
endif()

if(DEFINED ENV{SSAM_UPDATE_GOLDENS} AND NOT "$ENV{SSAM_UPDATE_GOLDENS}" STREQUAL "0" AND UPDATE)
  get_filename_component(dir ${GOLDEN} DIRECTORY)
  file(MAKE_DIRECTORY ${dir})
  file(COPY_FILE ${OUT} ${GOLDEN})
  message(STATUS "re-baselined ${GOLDEN}")
  return()
endif()
if(NOT EXISTS ${GOLDEN})
  message(FATAL_ERROR "no golden ${GOLDEN}: render it with SSAM_UPDATE_GOLDENS=1 ctest -L capture")
endif()

set(limits --fail ${FAIL} --warn ${FAIL} --failpercent ${FAILPERCENT} --warnpercent ${FAILPERCENT})
if(DEFINED HARDFAIL)
  list(APPEND limits --hardfail ${HARDFAIL} --hardwarn ${HARDFAIL})
endif()
set(diff ${OUT}.diff.png)
file(REMOVE ${diff})
execute_process(COMMAND ${IDIFF} ${OUT} ${GOLDEN} ${limits} RESULT_VARIABLE same OUTPUT_VARIABLE report)
message(STATUS "${report}")
if(NOT same EQUAL 0)
  execute_process(COMMAND ${IDIFF} ${OUT} ${GOLDEN} ${limits} --diff ${diff} --scale 8 OUTPUT_QUIET)
  message(FATAL_ERROR "${OUT} differs from ${GOLDEN} (ssam-idiff exit ${same}); difference x8 in ${diff}")
endif()

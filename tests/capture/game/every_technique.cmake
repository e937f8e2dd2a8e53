# SPDX-License-Identifier: MIT
# Every name of transparency::allTechniques() is accepted by racer --technique, and each run
# either renders (exit 0, a capture) or exits non-zero with the engine::Error saying why
# ("racer: error: ..." naming it): never a crash, never a silent fallback.
separate_arguments(args UNIX_COMMAND "${ARGS}")
foreach(name ssam ssam-plus alpha-test a2c blend-unsorted blend-sorted wboit reference)
  set(png ${OUT}/every_${name}.png)
  file(REMOVE ${png})
  execute_process(COMMAND ${RACER} ${args} --technique ${name} --capture ${png}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE err)
  if(rc EQUAL 0)
    if(NOT EXISTS ${png} OR NOT log MATCHES "racer: ${name}, ")
      message(FATAL_ERROR "--technique ${name}: exit 0 but no capture or not that technique:\n${log}")
    endif()
    message(STATUS "${name}: rendered")
  elseif(rc EQUAL 1 AND err MATCHES "racer: error: [^\n]*${name}")
    string(REGEX MATCH "racer: error: [^\n]*" why "${err}")
    message(STATUS "${name}: refused: ${why}")
  else()
    message(FATAL_ERROR "--technique ${name}: exit ${rc} without the technique's error:\n${log}\n${err}")
  endif()
endforeach()

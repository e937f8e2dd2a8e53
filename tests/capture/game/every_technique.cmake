# SPDX-License-Identifier: MIT
# Every name of transparency::allTechniques() is accepted by racer --technique, and each run
# either renders (exit 0, a capture) or exits 1 with the engine::Error saying why
# ("racer: error: ..."): never a crash, never a silent fallback. MUST_RENDER lists the ones this
# backend must render (a refusal of one fails the test).
cmake_minimum_required(VERSION 3.20)  # IN_LIST in a -P script
separate_arguments(args UNIX_COMMAND "${ARGS}")
set(techniques ssam ssam-plus alpha-test a2c blend-unsorted blend-sorted wboit reference hashed a2c8 hashed+taa
    alpha-test+taa a2c-sharp a2c8-sharp ssam+taa)
foreach(name IN LISTS techniques)
  set(png ${OUT}/every_${name}.png)
  file(REMOVE ${png})
  execute_process(COMMAND ${RACER} ${args} --technique ${name} --capture ${png}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE err)
  if(rc EQUAL 0)
    string(FIND "${log}" "racer: ${name}, " said)  # FIND: `+` in a name is no regex
    if(NOT EXISTS ${png} OR said EQUAL -1)
      message(FATAL_ERROR "--technique ${name}: exit 0 but no capture or not that technique:\n${log}")
    endif()
    message(STATUS "${name}: rendered")
  elseif(rc EQUAL 1 AND err MATCHES "racer: error: ")
    string(REGEX MATCH "racer: error: [^\n]*" why "${err}")
    if(name IN_LIST MUST_RENDER)
      message(FATAL_ERROR "--technique ${name} must render on this backend but: ${why}")
    endif()
    message(STATUS "${name}: refused: ${why}")
  else()
    message(FATAL_ERROR "--technique ${name}: exit ${rc} without the technique's error:\n${log}\n${err}")
  endif()
endforeach()

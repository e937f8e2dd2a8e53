# SPDX-License-Identifier: MIT
# One ssam-bench run for the check scripts beside this one (included after their fail()):
# BENCH with the arguments given and --out DIR, DIR emptied first; fails on a non-zero exit, or
# when CSV, the file the run must write there, is missing.
function(run_bench dir csv)
  file(REMOVE_RECURSE ${dir})
  execute_process(COMMAND ${BENCH} ${ARGN} --out ${dir}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
  if(NOT rc EQUAL 0)
    fail("exited with ${rc}\n${stdout}\n${stderr}")
  endif()
  if(NOT EXISTS ${dir}/${csv})
    fail("${dir}/${csv} was not written")
  endif()
endfunction()

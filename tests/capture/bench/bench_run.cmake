# SPDX-License-Identifier: MIT
# What the check scripts beside this one share (included after their fail()).

# One ssam-bench run: BENCH with the arguments given and --out DIR, DIR emptied first; fails on a
# non-zero exit, or when CSV, the file the run must write there, is missing.
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

# Fails unless DIR_ONE/CSV and DIR_TWO/CSV, the same run on one thread and on two, are the same.
function(expect_same_for_any_threads csv dirOne dirTwo)
  file(READ ${dirOne}/${csv} one)
  file(READ ${dirTwo}/${csv} two)
  if(NOT one STREQUAL two)
    fail("${csv} differs between one thread and two:\n${one}\n${two}")
  endif()
endfunction()

# The rows of the CSV FILE into OUT; fails unless its header is HEADER and it has COUNT rows
# (WHAT: which rows those are).
function(csv_rows file header count what out)
  file(STRINGS ${file} lines)
  list(POP_FRONT lines first)
  if(NOT first STREQUAL header)
    fail("${file}: header '${first}'")
  endif()
  list(LENGTH lines rows)
  if(NOT rows EQUAL count)
    fail("${file}: ${rows} rows, expected ${count} (${what})")
  endif()
  set(${out} "${lines}" PARENT_SCOPE)
endfunction()

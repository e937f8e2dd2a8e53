# SPDX-License-Identifier: MIT
# Runs `ssam-bench --quick` twice (BENCH, OUT) and checks its outputs:
#   - both runs exit 0;
#   - bench.csv has every required column and one row per scene x technique (+ opaque-only);
#   - where the exact reference exists, a row that ran has finite error columns; where it does
#     not, the error columns are empty and the note says so;
#   - bench.md and bench.svg exist, the SVG opens with <svg ...> and closes with </svg>;
#   - the two runs (the second on one thread) give identical error columns: the soft backend
#     is deterministic for any thread count;
#   - the tree and forest rows have the temporal measures (bench_temporal.hpp), finite;
#   - --figures writes FIGURES.md (bench_figures.hpp) from the run: the command at its top, the
#     goals (still, in motion, along the dolly) and what limits those not met, the forest's dolly
#     (bench_figures_runs.hpp), SSAM beside what engines ship; and FIGURES_ROWS.md beside it: the
#     same command, a table per scene with every technique, the forest's motions; in both pages
#     every table row as wide as its header.
cmake_minimum_required(VERSION 3.20)  # IN_LIST and the other modern if() forms in -P scripts
set(required scene technique backend width height time_ms_median time_ms_min time_ms_max rmse_linear
    psnr_srgb ssim flip_mean flicker peak_mem_mb)
set(deterministic rmse_linear psnr_linear rmse_srgb psnr_srgb ssim flip_mean flicker flicker_raw peak_mem_mb
    temporal_flip temporal_flip_worst temporal_rmse temporal_rmse_worst)
set(scenes tree forest vista empty)
set(techniques opaque-only ssam ssam-plus alpha-test a2c blend-unsorted blend-sorted wboit reference hashed a2c8
    hashed+taa alpha-test+taa a2c-sharp a2c8-sharp ssam+taa)

function(fail what)
  message(FATAL_ERROR "ssam-bench quick run: ${what}")
endfunction()

# Splits a CSV line into a CMake list (the last column, the note, may hold anything: it is
# cut off after the column count so its commas and semicolons do no harm).
function(csv_fields line out)
  string(REPLACE ";" "_" line "${line}")
  string(REPLACE "," ";" fields "${line}")
  set(${out} "${fields}" PARENT_SCOPE)
endfunction()

# Fails with <message> unless <text> matches every regular expression that follows.
function(expect_matches text message)
  foreach(regex IN LISTS ARGN)
    if(NOT text MATCHES "${regex}")
      fail("${message}")
    endif()
  endforeach()
endfunction()

function(run_once dir)
  file(REMOVE_RECURSE ${dir})
  execute_process(COMMAND ${BENCH} --quick --out ${dir} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
  if(NOT rc EQUAL 0)
    fail("exited with ${rc}\n${stdout}\n${stderr}")
  endif()
  foreach(f bench.csv bench_passes.csv bench.md bench.svg)
    if(NOT EXISTS ${dir}/${f})
      fail("did not write ${dir}/${f}")
    endif()
  endforeach()
endfunction()

run_once(${OUT}/run1 --figures ${OUT}/run1/FIGURES.md)
run_once(${OUT}/run2 --threads 1)  # also: the same numbers for any soft-backend thread count

file(STRINGS ${OUT}/run1/bench.csv lines1)
file(STRINGS ${OUT}/run2/bench.csv lines2)
list(GET lines1 0 header)
csv_fields("${header}" columns)
foreach(c IN LISTS required)
  list(FIND columns ${c} at)
  if(at LESS 0)
    fail("bench.csv header '${header}' lacks column '${c}'")
  endif()
endforeach()
list(FIND columns note noteAt)
list(FIND columns time_ms_median timeAt)

list(LENGTH lines1 n1)
list(LENGTH lines2 n2)
list(LENGTH scenes ns)
list(LENGTH techniques nt)
math(EXPR expected "${ns} * ${nt} + 1")
if(NOT n1 EQUAL expected OR NOT n2 EQUAL expected)
  fail("bench.csv has ${n1} and ${n2} lines, expected the header and ${ns} x ${nt} rows")
endif()

set(seen "")
math(EXPR last "${n1} - 1")
foreach(i RANGE 1 ${last})
  list(GET lines1 ${i} line1)
  list(GET lines2 ${i} line2)
  csv_fields("${line1}" f1)
  csv_fields("${line2}" f2)
  list(GET f1 0 scene)
  list(GET f1 1 technique)
  list(GET f1 2 backend)
  if(NOT scene IN_LIST scenes OR NOT technique IN_LIST techniques OR NOT backend STREQUAL "soft")
    fail("unexpected row '${line1}'")
  endif()
  if("${scene}/${technique}" IN_LIST seen)
    fail("two rows for ${scene}/${technique}")
  endif()
  list(APPEND seen "${scene}/${technique}")

  list(LENGTH f1 nf)
  set(note "")
  if(nf GREATER noteAt)
    list(SUBLIST f1 ${noteAt} -1 noteParts)
    string(JOIN "," note ${noteParts})
  endif()
  list(GET f1 ${timeAt} time)
  if(time STREQUAL "")
    if(NOT note MATCHES "^\"?skipped: ")
      fail("row '${line1}' has no time and no 'skipped:' note")
    endif()
    continue()
  endif()

  foreach(c IN LISTS deterministic)
    list(FIND columns ${c} at)
    list(GET f1 ${at} v1)
    list(GET f2 ${at} v2)
    if(NOT v1 STREQUAL v2)
      fail("${scene}/${technique}: ${c} differs between two runs: '${v1}' vs '${v2}'")
    endif()
    set(finite FALSE)
    if(v1 MATCHES "^-?[0-9]+(\\.[0-9]+)?(e[-+][0-9]+)?$")
      set(finite TRUE)
    endif()
    set(needed TRUE)
    if(c MATCHES "^(flicker|temporal)" AND NOT scene MATCHES "^(tree|forest)$")
      set(needed FALSE)  # only the tree and forest scenes have a pan
    endif()
    if(c MATCHES "^temporal" AND technique STREQUAL "opaque-only")
      set(needed FALSE)  # the judge of which pixels are foliage, not judged itself
    endif()
    if(note MATCHES "no reference" AND NOT c MATCHES "^(flicker_raw|peak_mem_mb)$")
      if(NOT v1 STREQUAL "")
        fail("${scene}/${technique}: ${c} = '${v1}' without a reference")
      endif()
    elseif(needed)
      # PSNR is +infinity exactly when the frame equals the reference (RMSE 0).
      if(NOT finite AND NOT (c MATCHES "^psnr" AND v1 STREQUAL "inf"))
        fail("${scene}/${technique}: ${c} = '${v1}' is not a finite number")
      endif()
    endif()
  endforeach()
endforeach()

file(READ ${OUT}/run1/bench.svg svg)
string(STRIP "${svg}" svg)
expect_matches("${svg}" "bench.svg does not open with <svg ...> and close with </svg>"
               "^<svg [^>]*xmlns=\"http://www.w3.org/2000/svg\"" "</svg>$")
string(REGEX MATCHALL "<svg[ >]" opens "${svg}")
string(REGEX MATCHALL "</svg>" closes "${svg}")
list(LENGTH opens no)
list(LENGTH closes nc)
if(NOT no EQUAL 1 OR NOT nc EQUAL 1)
  fail("bench.svg has ${no} <svg> and ${nc} </svg>")
endif()
file(READ ${OUT}/run1/bench.md md)
expect_matches("${md}" "bench.md lacks the results table or the goals" "\\| scene \\| technique \\|" "## goals")
file(STRINGS ${OUT}/run1/FIGURES.md figures ENCODING UTF-8)
list(GET figures 0 first)
if(NOT first STREQUAL "# Current figures")
  fail("FIGURES.md opens with '${first}'")
endif()
file(READ ${OUT}/run1/FIGURES.md figuresText)
expect_matches("${figuresText}" "FIGURES.md lacks the command that wrote it, the goals or what limits them"
               "`ssam-bench --quick --out [^`]*--figures [^`]*FIGURES.md`" "\n## Goals\n"
               "\\| forest wind: flicker ssam / alpha-test \\| [0-9.-]+x \\|"
               "\\| forest dolly: popping \\(pop_lod\\) ssam / hashed \\| [0-9.]+x \\|"
               "\n(Every goal measured in this run is met|What limits each goal not met in this run)"
               "\n## Along the dolly\n[^#]*\\| `hashed` \\| [0-9.]+ \\|"
               "\n## SSAM and what engines ship\n.*\\| forest wind \\| ghosting converged \\|"
               "\\(FIGURES_ROWS.md#ssam-against-its-rivals\\)")
if(NOT EXISTS ${OUT}/run1/FIGURES_ROWS.md)
  fail("--figures did not write FIGURES_ROWS.md beside FIGURES.md")
endif()
file(STRINGS ${OUT}/run1/FIGURES_ROWS.md rowsLines ENCODING UTF-8)
file(READ ${OUT}/run1/FIGURES_ROWS.md rowsText)
expect_matches("${rowsText}" "FIGURES_ROWS.md lacks the command that wrote it or the motions"
               "`ssam-bench --quick --out [^`]*--figures [^`]*FIGURES.md`"
               "\n## In motion\n[^#]*\\| dolly \\| `a2c-sharp` \\| [0-9.-]+ \\|")
foreach(scene IN LISTS scenes)
  string(FIND "${rowsText}" "### ${scene}, soft" at)
  if(at LESS 0)
    fail("FIGURES_ROWS.md has no table for ${scene}")
  endif()
  string(SUBSTRING "${rowsText}" ${at} -1 rest)
  string(FIND "${rest}" "\n\n" headEnd)
  math(EXPR tableStart "${headEnd} + 2")
  string(SUBSTRING "${rest}" ${tableStart} -1 rest)
  string(FIND "${rest}" "\n\n" tableEnd)
  string(SUBSTRING "${rest}" 0 ${tableEnd} table)
  foreach(technique IN LISTS techniques)
    string(REPLACE "+" "\\+" escaped "${technique}")
    if(NOT table MATCHES "\\| `?${escaped}`? \\|")
      fail("FIGURES_ROWS.md's ${scene} table lacks ${technique}")
    endif()
  endforeach()
endforeach()
# Every table row has as many cells as the header above it, in both pages.
set(FIGURES.md_lines "${figures}")
set(FIGURES_ROWS.md_lines "${rowsLines}")
foreach(page FIGURES.md FIGURES_ROWS.md)
  set(width -1)
  foreach(line IN LISTS ${page}_lines)
    if(line MATCHES "^\\|")
      string(REPLACE "\\|" "" bare "${line}")
      string(REGEX MATCHALL "\\|" bars "${bare}")
      list(LENGTH bars n)
      if(width LESS 0)
        set(width ${n})
      elseif(NOT n EQUAL width)
        fail("${page}: row '${line}' has ${n} bars, its header ${width}")
      endif()
    else()
      set(width -1)
    endif()
  endforeach()
endforeach()
message(STATUS "ssam-bench quick run: ${n1} lines, outputs complete, error columns identical across two runs")

# SPDX-License-Identifier: MIT
# Runs `ssam-bench --motion pan,dolly,wind,car` (BENCH, OUT) over a few frames at a small size and checks:
#   - motion.csv has one row per technique and motion, in the forest, each with the frames run;
#   - every measure is a number (flicker may be negative: less than the reference's), the
#     wind moves pixels (ghost_frames > 0) and the pan and dolly too;
#   - two runs, on one thread and on two, write the same file byte for byte;
#   - --motion-vectors off changes hashed+taa's wind and car rows (the plants' and the car's motion
#     reach the temporal pass) and nothing of alpha-test's (no history).
cmake_minimum_required(VERSION 3.20)

function(fail what)
  message(FATAL_ERROR "ssam-bench --motion: ${what}")
endfunction()

include(${CMAKE_CURRENT_LIST_DIR}/bench_run.cmake)

function(run dir threads vectors)
  run_bench(${dir} motion.csv --motion pan,dolly,wind,car --motion-frames 3 --size 96x54
            --techniques hashed+taa,alpha-test --motion-vectors ${vectors} --threads ${threads})
endfunction()

run(${OUT}/one 1 on)
run(${OUT}/two 2 on)
run(${OUT}/off 2 off)
expect_same_for_any_threads(motion.csv ${OUT}/one ${OUT}/two)
set(header "scene,motion,technique,backend,motion_vectors,frames,flicker,flip,flip_worst,rmse,rmse_worst,ghost_frames,ghost,ghost_worst")
set(which "pan, dolly, wind, car for hashed+taa and alpha-test")
csv_rows(${OUT}/one/motion.csv "${header}" 8 "${which}" lines)
csv_rows(${OUT}/off/motion.csv "${header}" 8 "${which}" offLines)
set(i 0)
foreach(row IN LISTS lines)
  list(GET offLines ${i} offRow)
  math(EXPR i "${i} + 1")
  string(REPLACE "," ";" f "${row}")
  list(GET f 0 scene)
  list(GET f 1 motion)
  list(GET f 2 technique)
  list(GET f 5 frames)
  list(GET f 11 ghostFrames)
  if(NOT scene STREQUAL "forest" OR NOT frames EQUAL 3 OR NOT ghostFrames GREATER 0)
    fail("row '${row}': expected the forest, 3 frames, moved pixels in some")
  endif()
  foreach(at 6 7 8 9 10 12 13)
    list(GET f ${at} v)
    if(NOT v MATCHES "^-?[0-9]+\\.[0-9]+$")
      fail("row '${row}': column ${at} '${v}' is not a number")
    endif()
  endforeach()
  # The measures without the motion_vectors column: off changes only the temporal wind and car rows.
  string(REGEX REPLACE ",o(n|ff)," "," measures "${row}")
  string(REGEX REPLACE ",o(n|ff)," "," offMeasures "${offRow}")
  if(technique STREQUAL "hashed+taa" AND (motion STREQUAL "wind" OR motion STREQUAL "car"))
    if(measures STREQUAL offMeasures)
      fail("hashed+taa, ${motion}: the same row with motion vectors on and off ('${row}')")
    endif()
  elseif(NOT measures STREQUAL offMeasures)
    fail("'${row}' changed with --motion-vectors off: '${offRow}'")
  endif()
endforeach()

# SPDX-License-Identifier: MIT
# Runs `ssam-bench --dolly` (BENCH, OUT) over the dolly's first frames at a small size and checks:
#   - dolly.csv has one row per technique, each with the frames run and the path's fixed step;
#   - every measure is a number in [0, 1], and the camera's motion shows (pop > 0);
#   - two runs, on one thread and on two, write the same file byte for byte: the path and
#     the measures are deterministic.
cmake_minimum_required(VERSION 3.20)

function(fail what)
  message(FATAL_ERROR "ssam-bench --dolly: ${what}")
endfunction()

include(${CMAKE_CURRENT_LIST_DIR}/bench_run.cmake)

function(run dir threads)
  run_bench(${dir} dolly.csv --dolly --dolly-frames 6 --size 96x54 --techniques ssam,alpha-test --threads ${threads})
endfunction()

run(${OUT}/one 1)
run(${OUT}/two 2)
expect_same_for_any_threads(dolly.csv ${OUT}/one ${OUT}/two)
csv_rows(${OUT}/one/dolly.csv
         "scene,technique,backend,frames,step_m,crossfade,pop_flip,pop_frame,pop_lod_flip,pop_lod_frame,lod_flip_mean,lod_flip_worst,lod_frame_flip_mean"
         2 "ssam, alpha-test" lines)
foreach(row IN LISTS lines)
  string(REPLACE "," ";" f "${row}")
  list(GET f 0 scene)
  list(GET f 3 frames)
  list(GET f 4 step)
  list(GET f 5 crossfade)
  if(NOT scene STREQUAL "forest" OR NOT frames EQUAL 6 OR NOT step STREQUAL "1.00" OR NOT crossfade STREQUAL "0.10")
    fail("row '${row}': expected the forest, 6 frames of 1.00 m, crossfade 0.10")
  endif()
  foreach(at 6 8 10 11 12)
    list(GET f ${at} v)
    if(NOT v MATCHES "^[0-9]+\\.[0-9]+$" OR v GREATER 1)
      fail("row '${row}': column ${at} '${v}' is not a number in [0, 1]")
    endif()
  endforeach()
  list(GET f 6 pop)
  if(NOT pop GREATER 0)
    fail("row '${row}': no change between frames of a moving camera")
  endif()
endforeach()

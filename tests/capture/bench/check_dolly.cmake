# SPDX-License-Identifier: MIT
# Runs `ssam-bench --dolly` (BENCH, OUT) over the dolly's first frames at a small size and checks:
#   - dolly.csv has one row per technique, each with the frames run and the path's fixed step;
#   - every measure is a number in [0, 1], and the camera's motion shows (pop > 0);
#   - dolly_frames.csv has each technique's frames in order, the first without a change, and
#     its largest change and excess are dolly.csv's pop and pop_lod, at their frames;
#   - two runs, on one thread and on two, write the same files byte for byte: the path and
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
expect_same_for_any_threads(dolly_frames.csv ${OUT}/one ${OUT}/two)
csv_rows(${OUT}/one/dolly_frames.csv "scene,technique,frame,change_flip,lod_excess_flip,lod_flip" 12
         "6 frames each of ssam, alpha-test" frameLines)
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
  # The worst frames of dolly_frames.csv are dolly.csv's (both printed to 5 decimals).
  list(GET f 1 technique)
  list(GET f 7 popFrame)
  list(GET f 8 popLod)
  list(GET f 9 popLodFrame)
  set(expectFrame 0)
  set(worstChange 0)
  set(worstExcess 0)
  foreach(frameLine IN LISTS frameLines)
    string(REPLACE "," ";" g "${frameLine}")
    list(GET g 1 t)
    if(NOT t STREQUAL technique)
      continue()
    endif()
    list(GET g 2 frame)
    list(GET g 3 change)
    list(GET g 4 excess)
    list(GET g 5 lodFlip)
    if(NOT frame EQUAL expectFrame OR NOT lodFlip MATCHES "^[0-9]+\\.[0-9]+$")
      fail("dolly_frames.csv line '${frameLine}': expected frame ${expectFrame} with its LOD ꟻLIP")
    endif()
    math(EXPR expectFrame "${expectFrame} + 1")
    if(frame EQUAL 0)
      if(NOT change STREQUAL "" OR NOT excess STREQUAL "")
        fail("dolly_frames.csv line '${frameLine}': the first frame has no frame before it to change from")
      endif()
      continue()
    endif()
    if(change GREATER worstChange)
      set(worstChange ${change})
      set(worstChangeFrame ${frame})
    endif()
    if(excess GREATER worstExcess)
      set(worstExcess ${excess})
      set(worstExcessFrame ${frame})
    endif()
  endforeach()
  if(NOT expectFrame EQUAL 6 OR NOT worstChange EQUAL pop OR NOT worstChangeFrame EQUAL popFrame
     OR NOT worstExcess EQUAL popLod OR NOT worstExcessFrame EQUAL popLodFrame)
    fail("${technique}: dolly_frames.csv's worst change ${worstChange} at ${worstChangeFrame} and excess "
         "${worstExcess} at ${worstExcessFrame} are not dolly.csv's ${pop} at ${popFrame} and ${popLod} at ${popLodFrame}")
  endif()
endforeach()

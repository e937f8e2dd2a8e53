# SPDX-License-Identifier: MIT
# racer --backend soft in a window (under xvfb-run) and headless, same flags: the captures
# must be byte-identical (the window only shows the soft frame; the simulation steps alike).
include(${CMAKE_CURRENT_LIST_DIR}/racer_runs.cmake)
separate_arguments(args UNIX_COMMAND "${ARGS}")
file(REMOVE ${OUT}/window_soft.png ${OUT}/headless_soft.png)
racer_window_capture(${OUT}/window_soft.png "backend soft.*, window" "")
racer_headless_capture(${OUT}/headless_soft.png)
expect_same_file(${OUT}/window_soft.png ${OUT}/headless_soft.png "the window's soft frame differs from the headless capture")

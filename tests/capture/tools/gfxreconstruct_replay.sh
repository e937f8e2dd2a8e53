#!/bin/sh
# SPDX-License-Identifier: MIT
# gfxreconstruct_replay.sh EXAMPLE CHECK DIR: records EXAMPLE (ssam_vk_embedding) with
# gfxreconstruct's capture layer while it draws three frames (two in flight) and presents each
# (--present: a window, here on Xvfb; the presents are the frame boundaries the layer counts),
# keeping only the last frame (GFXRECON_CAPTURE_FRAMES=3: a trimmed capture, the state the frame
# starts from written as the layer found it, then the frame's calls). gfxrecon-replay replays that
# frame on lavapipe, under the validation layer (--validate; the capture's instance asks for
# synchronization validation, so the replay gets it too), and writes a screenshot at its present:
# the swapchain image the frame blitted its colour image into. --use-captured-swapchain-indices:
# 0.9.18's default virtual swapchain blits its own image to the window's with a barrier whose
# dstAccessMask is TRANSFER_WRITE for the blit's source (a read), which synchronization validation
# reports as SYNC-HAZARD-READ-AFTER-WRITE; with the captured indices the frame presents the
# replay's swapchain images directly. (It then warns that the trimmed capture's image count
# differs from the replay's; the screenshot is still the frame's, bit for bit.) The screenshot (BGRA BMP,
# read back as RGBA) must equal the PNG the program wrote bit for bit (CHECK --same) and pass the
# examples' pixel checks; neither run may report a validation message (the example fails on any
# with --validation, which runs beside the capture layer: app -> capture -> validation -> driver).
# Exits 77 (ctest: skipped) only where gfxreconstruct or xvfb-run is not installed (Debian:
# gfxreconstruct, xvfb; `make deps`), or where the example finds no Vulkan device (its own 77).
# shellcheck source=tests/capture/tools/replay_checks.sh
. "$(dirname "$0")/replay_checks.sh"
example=$1 check=$2 dir=$3
if [ "${4:-}" != --on-display ]; then
  command -v gfxrecon-replay >/dev/null || {
    echo "gfxreconstruct not installed (Debian: gfxreconstruct; make deps): skipped"
    exit 77
  }
  command -v xvfb-run >/dev/null || { echo "xvfb-run not installed (Debian: xvfb; make deps): skipped"; exit 77; }
  rm -rf "$dir" && mkdir -p "$dir" || exit 1
  # xvfb-run -a can lose the race for a display number to another one starting at the same moment
  # (parallel ctest): that is retried, three attempts in all, nothing else is.
  for attempt in 1 2 3; do
    xvfb-run -a -s "-screen 0 1024x768x24" sh "$0" "$example" "$check" "$dir" --on-display >"$dir/run.log" 2>&1
    rc=$?
    cat "$dir/run.log"
    grep -Eq 'xvfb-run: error|Xvfb failed to start|Server is already active' "$dir/run.log" || exit $rc
    sleep 1
  done
  exit $rc
fi

# On the Xvfb display. Capture: the program runs as always, with the layer in the environment.
VK_INSTANCE_LAYERS=VK_LAYER_LUNARG_gfxreconstruct GFXRECON_CAPTURE_FILE="$dir/ssam_vk.gfxr" \
  GFXRECON_CAPTURE_FILE_TIMESTAMP=false GFXRECON_CAPTURE_FRAMES=3 \
  "$example" --validation --present --frames 3 --out "$dir/frame.png" || exit $?
capture=$dir/ssam_vk_frame_3.gfxr  # the layer names a trimmed capture by its frames
[ -s "$capture" ] || { echo "FAIL: no capture $capture (is VK_LAYER_LUNARG_gfxreconstruct installed?)"; exit 1; }

# Replay: the trimmed capture holds one frame, its screenshot is frame 1.
replay gfxrecon-replay "$dir/replay.log" -Eq '\] (ERROR|FATAL)|Validation (Error|Warning)' \
  gfxrecon-replay --validate --use-captured-swapchain-indices --screenshots 1 --screenshot-dir "$dir" \
  --screenshot-prefix replayed "$capture"
same_frame gfxrecon-replay "$dir/replayed_frame_1.bmp" "$check" "$dir/frame.png"

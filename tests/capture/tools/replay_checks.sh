# SPDX-License-Identifier: MIT
# shellcheck shell=sh
# What every capture-replay test (apitrace_replay.sh, gfxreconstruct_replay.sh) checks of its
# replay, sourced by each: the replayer ran cleanly, and its image is the program's own frame.

# replay TOOL LOG GREP ERRORS COMMAND...: runs COMMAND (the replayer TOOL) with its output in LOG,
# shows LOG, and fails when it exits non-zero or a line of LOG matches ERRORS, the lines where it
# reports errors or warnings (GREP: grep's flags for that pattern, -Eq or -Eiq).
replay() {
  tool=$1 log=$2 flags=$3 errors=$4
  shift 4
  "$@" >"$log" 2>&1
  rc=$?
  cat "$log"
  [ $rc -eq 0 ] || { echo "FAIL: $tool exited $rc"; exit 1; }
  if grep "$flags" "$errors" "$log"; then
    echo "FAIL: $tool reported errors or warnings (the capture does not replay as recorded)"
    exit 1
  fi
}

# same_frame TOOL REPLAYED CHECK FRAME: the replay's image REPLAYED must exist, equal the
# program's FRAME bit for bit (CHECK --same) and pass the examples' pixel checks (CHECK).
same_frame() {
  [ -f "$2" ] || { echo "FAIL: $1 wrote no image $2"; exit 1; }
  "$3" --same "$4" "$2" || exit 1
  exec "$3" "$2"
}

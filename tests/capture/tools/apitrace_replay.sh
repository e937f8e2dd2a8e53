#!/bin/sh
# SPDX-License-Identifier: MIT
# apitrace_replay.sh EXAMPLE CHECK DIR: records EXAMPLE (ssam_gl_embedding, headless on Mesa's
# surfaceless EGL) with apitrace's EGL wrapper, replays the trace with eglretrace on surfaceless
# EGL (waffle's surfaceless_egl platform, --headless) and snapshots the host's colour target at
# the program's own readback (its first glReadPixels: the draw framebuffer there is the host's,
# whose colour attachment is the texture it reads). The snapshot must equal the PNG the program
# wrote bit for bit (CHECK --same, RGBA) and pass the examples' pixel checks; eglretrace must
# report no GL error or warning. Exits 77 (ctest: skipped) only where apitrace, its EGL wrapper
# or eglretrace is not installed (Debian: apitrace, apitrace-tracers; `make deps`), or where the
# example finds no OpenGL 3.3 context (its own 77).
# shellcheck source=tests/capture/tools/replay_checks.sh
. "$(dirname "$0")/replay_checks.sh"
example=$1 check=$2 dir=$3
apitrace=$(command -v apitrace) && eglretrace=$(command -v eglretrace) || {
  echo "apitrace or eglretrace not installed (Debian: apitrace; make deps): skipped"
  exit 77
}
wrapper=
for w in "${apitrace%/bin/apitrace}"/lib/*/apitrace/wrappers/egltrace.so "${apitrace%/bin/apitrace}"/lib/apitrace/wrappers/egltrace.so; do
  [ -f "$w" ] && wrapper=$w
done
if [ -z "$wrapper" ]; then
  echo "apitrace's egltrace.so not installed (Debian: apitrace-tracers; make deps): skipped"
  exit 77
fi
rm -rf "$dir" && mkdir -p "$dir" || exit 1
trace=$dir/ssam_gl.trace

# Capture: the program runs as always, under egltrace.so (LD_PRELOAD), writing its frame.
apitrace trace --api egl --output "$trace" "$example" --egl surfaceless --out "$dir/frame.png" || exit $?
[ -s "$trace" ] || { echo "FAIL: apitrace wrote no trace $trace"; exit 1; }

# The call number of the program's readback of its frame.
call=$(apitrace dump --color=never "$trace" | sed -n 's/^\([0-9][0-9]*\) glReadPixels(.*/\1/p' | head -n 1)
[ -n "$call" ] || { echo "FAIL: no glReadPixels in $trace"; exit 1; }
echo "the program reads its frame back at call $call"

# Replay, headless: a snapshot (RGBA PNG) after that call.
replay eglretrace "$dir/eglretrace.log" -Eiq '(^|[^a-z])(error|warning):' \
  env WAFFLE_PLATFORM=surfaceless_egl "$eglretrace" --headless --snapshot-alpha --call-nos=no -S "$call" \
  -s "$dir/replayed-" "$trace"
same_frame eglretrace "$dir/replayed-0000000000.png" "$check" "$dir/frame.png"

#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `make fuzz`: builds the fuzz targets as libFuzzer binaries (Clang, ASan + UBSan) in their own
# build directory and runs each for FUZZ_SECONDS on a copy of its seed corpus.
#
#   FUZZ_SECONDS=60     per target (0: build only)
#   FUZZ_TARGETS="gltf_glb gltf_text image_decode capture_image racer_flags"
#   FUZZ_BUILD_DIR=build-fuzz   FUZZ_OUT=out/fuzz   FUZZ_BUILD_JOBS=$(nproc)
#
# Corpora grow in $FUZZ_OUT/<target>/corpus (the committed seeds stay as they are); crashes,
# hangs (timeout-*), leaks and sanitizer reports are written next to it as crash-*, timeout-*,
# leak-* files with the libFuzzer log in $FUZZ_OUT/<target>/fuzz.log. A reproducer goes into
# tests/fuzz/corpus/<target>/ as regress_<what>, where the ctest replay keeps it fixed.
# Exits 1 if any target found something.
set -uo pipefail
cd "$(dirname "$0")/../.."

seconds=${FUZZ_SECONDS:-60}
targets=${FUZZ_TARGETS:-gltf_glb gltf_text image_decode capture_image racer_flags}
build=${FUZZ_BUILD_DIR:-build-fuzz}
out=${FUZZ_OUT:-out/fuzz}
jobs=${FUZZ_BUILD_JOBS:-$(nproc)}

if ! command -v clang++ >/dev/null; then
  echo "make fuzz needs Clang with libFuzzer (Debian: apt-get install clang)" >&2
  exit 2
fi

# Every library the targets link is instrumented for coverage and the sanitizers; only the
# fuzz targets get libFuzzer's main() (tests/fuzz/CMakeLists.txt). -O1 with assertions on.
sanitize="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S . -B "$build" -DSSAM_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
    -DCMAKE_C_FLAGS="$sanitize" -DCMAKE_CXX_FLAGS="$sanitize" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" || exit 1
fi
cmake --build "$build" -j "$jobs" --target $(printf 'fuzz_%s ' $targets) || exit 1
[ "$seconds" = 0 ] && exit 0

found=0
for target in $targets; do
  dir="$out/$target"
  mkdir -p "$dir/corpus"
  cp -n tests/fuzz/corpus/"$target"/* "$dir/corpus/"
  dict=()  # gltf_glb and gltf_text share gltf.dict
  [ -f "tests/fuzz/${target%%_*}.dict" ] && dict=(-dict="tests/fuzz/${target%%_*}.dict")
  echo "fuzz_$target: ${seconds}s on $dir/corpus"
  # -timeout: one input taking 10 s is a hang; -rss_limit_mb: a huge allocation is a bug too.
  "$build/bin/fuzz_$target" "$dir/corpus" "${dict[@]}" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix="$dir/" >"$dir/fuzz.log" 2>&1
  status=$?
  grep -E '^stat::number_of_executed_units|^stat::peak_rss_mb|^#[0-9]+.*DONE' "$dir/fuzz.log" | sed 's/^/  /'
  if [ $status -ne 0 ]; then
    found=1
    echo "  FOUND a problem (exit $status): see $dir/fuzz.log and $dir/crash-* / timeout-* / leak-*"
  fi
done
exit $found

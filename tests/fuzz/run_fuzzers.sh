#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `make fuzz` and `make fuzz-campaign`: builds the fuzz targets as libFuzzer binaries (Clang,
# ASan + UBSan) in their own build directory and runs each for FUZZ_SECONDS on a copy of its
# seed corpus.
#
#   FUZZ_SECONDS=60       per target (0: build only, or with FUZZ_MERGE=1 only minimise)
#   FUZZ_TARGETS="gltf_glb gltf_text image_decode capture_image racer_flags"
#   FUZZ_BUILD_DIR=build-fuzz   FUZZ_OUT=out/fuzz   FUZZ_BUILD_JOBS=$(nproc)
#   FUZZ_CONCURRENT=0     1: every target at once (one process each), so a campaign of N
#                         targets takes FUZZ_SECONDS rather than N times it
#   FUZZ_NICE=0           niceness of the fuzzing processes (19 on a machine others share)
#   FUZZ_TIMEOUT=10       seconds one input may take before it counts as a hang
#   FUZZ_MERGE=0          1: afterwards minimise each grown corpus (-merge=1) into
#                         $FUZZ_OUT/<target>/minimised: the seeds plus what reaches more
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
concurrent=${FUZZ_CONCURRENT:-0}
niceness=${FUZZ_NICE:-0}
timeout=${FUZZ_TIMEOUT:-10}
merge=${FUZZ_MERGE:-0}

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
[ "$seconds" = 0 ] && [ "$merge" != 1 ] && exit 0

# fuzz_one <target>: fuzzes it for $seconds; the exit status is libFuzzer's (0: nothing found).
fuzz_one() {
  local target=$1 dir="$out/$1"
  mkdir -p "$dir/corpus"
  cp -n tests/fuzz/corpus/"$target"/* "$dir/corpus/"
  local dict=()  # gltf_glb and gltf_text share gltf.dict
  [ -f "tests/fuzz/${target%%_*}.dict" ] && dict=(-dict="tests/fuzz/${target%%_*}.dict")
  # -rss_limit_mb: a huge allocation is a bug too.
  nice -n "$niceness" "$build/bin/fuzz_$target" "$dir/corpus" "${dict[@]}" -max_total_time="$seconds" \
    -timeout="$timeout" -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix="$dir/" >"$dir/fuzz.log" 2>&1
}

# report <target> <status>: the final statistics, and whether it found something.
report() {
  local target=$1 status=$2 dir="$out/$1"
  echo "fuzz_$target: ${seconds}s on $dir/corpus"
  grep -E '^stat::number_of_executed_units|^stat::average_exec_per_sec|^stat::peak_rss_mb|^#[0-9]+.*DONE' \
    "$dir/fuzz.log" | sed 's/^/  /'
  if [ "$status" -ne 0 ]; then
    echo "  FOUND a problem (exit $status): see $dir/fuzz.log and $dir/crash-* / timeout-* / leak-*"
    return 1
  fi
}

found=0
declare -A pids=()
[ "$seconds" = 0 ] && targets_to_fuzz="" || targets_to_fuzz=$targets
for target in $targets_to_fuzz; do
  if [ "$concurrent" = 1 ]; then
    echo "fuzz_$target: started, log in $out/$target/fuzz.log"
    fuzz_one "$target" & pids[$target]=$!
  else
    fuzz_one "$target"
    report "$target" $? || found=1
  fi
done
for target in "${!pids[@]}"; do
  wait "${pids[$target]}"
  report "$target" $? || found=1
done

# Minimising: a fresh directory starts from the committed seeds (hand-written cases and
# regress_* reproducers stay whatever they cover), and -merge=1 adds from the grown corpus,
# smallest first, each input that reaches an edge nothing before it reached. Edges alone
# (-use_counters=0): counting how often each is hit as well kept twice as many files in
# the first campaign. What it adds is the part worth committing, copied by hand into
# tests/fuzz/corpus/<target>/ as grown_*.
if [ "$merge" = 1 ]; then
  for target in $targets; do
    dir="$out/$target"
    rm -rf "$dir/minimised" && mkdir -p "$dir/minimised"
    cp tests/fuzz/corpus/"$target"/* "$dir/minimised/"
    seeds=$(ls "$dir/minimised" | wc -l)
    nice -n "$niceness" "$build/bin/fuzz_$target" -merge=1 -use_counters=0 -timeout="$timeout" -rss_limit_mb=4096 \
      "$dir/minimised" "$dir/corpus" >"$dir/merge.log" 2>&1 || {
      echo "fuzz_$target: merge failed, see $dir/merge.log"; found=1; continue; }
    total=$(ls "$dir/minimised" | wc -l)
    echo "fuzz_$target: $seeds seeds + $((total - seeds)) new inputs in $dir/minimised," \
         "$(( $(cat "$dir/minimised"/* | wc -c) / 1024 )) KiB"
  done
fi
exit $found

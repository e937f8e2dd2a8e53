#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The soft backend's speed against Mesa llvmpipe, from one run on this machine:
#   racer's whole frame, pan and chase, 1280x720, every module on: soft / llvmpipe
#   ssam-bench tree, forest, vista: SSAM frame soft / llvmpipe (and the worst of the three)
#   forest: SSAM / alpha test on soft
#   racer's 160x90 chase frame (the fixed per-frame cost), ms
#   2 threads / 1 thread: racer's 720p chase frame on soft, speed-up
# Both backends get the same threads: soft --threads, llvmpipe LP_NUM_THREADS (EGL, headless).
# Times are racer's "mean frame" (every frame of the run, start-up frames included) and
# ssam-bench's median frame. Each racer measure runs ROUNDS times, alternating backends (and
# binaries), and the median is kept.
#
# With OLD_BIN set (a directory holding an older racer and ssam-bench), every soft measure is
# taken with both, alternately in the same run (old, new, old, new, ...), and the table gets a
# "before" column. With BEFORE=lod-off instead, the "before" column is BIN's binaries with
# --lod off (every plant at full detail), alternated the same way. llvmpipe is measured with
# BIN's binaries and the default levels of detail (the same Mesa either way), so each ratio has
# the same levels of detail on both backends.
#
# Usage: game/bench/speed_table.sh
#   (env: BIN=build/bin OUT=out/bench OLD_BIN= BEFORE= ROUNDS=3 THREADS=2)
set -euo pipefail
BIN=${BIN:-build/bin}
OUT=${OUT:-out/bench}
OLD_BIN=${OLD_BIN:-}
BEFORE=${BEFORE:-}
ROUNDS=${ROUNDS:-3}
THREADS=${THREADS:-2}
CONTENT=${CONTENT:-content}

die() { echo "speed_table: error: $*" >&2; exit 2; }
[[ "$ROUNDS" =~ ^[1-9][0-9]*$ ]] || die "ROUNDS='$ROUNDS' is not a positive integer"
[[ "$THREADS" =~ ^[1-9][0-9]*$ ]] || die "THREADS='$THREADS' is not a positive integer"
[[ -z "$BEFORE" || "$BEFORE" == lod-off ]] || die "BEFORE='$BEFORE': the one value is lod-off"
[[ -z "$BEFORE" || -z "$OLD_BIN" ]] || die "set OLD_BIN or BEFORE=lod-off, not both"
for b in "$BIN" ${OLD_BIN:+"$OLD_BIN"}; do
  for tool in racer ssam-bench; do [[ -x "$b/$tool" ]] || die "no executable $b/$tool"; done
done
mkdir -p "$OUT" || die "cannot create '$OUT'"
export DISPLAY=  # headless: llvmpipe through EGL
LOG="$OUT/speed_table.log"
: > "$LOG"

# A variant is what the soft measures run: "new" (BIN), "old" (OLD_BIN) or "lod-off" (BIN with
# --lod off). bins lists them in the order they alternate, the "before" one first.
bins=(new)
[[ -n "$OLD_BIN" ]] && bins=(old new)
[[ -n "$BEFORE" ]] && bins=(lod-off new)
variant_bin() { if [[ $1 == old ]]; then echo "$OLD_BIN"; else echo "$BIN"; fi; }
variant_args() { if [[ $1 == lod-off ]]; then echo "--lod off"; fi; }
before_label() { if [[ -n "$OLD_BIN" ]]; then echo "$OLD_BIN"; else echo "$BIN --lod off"; fi; }

# racer's mean frame in ms: racer_ms VARIANT BACKEND THREADS ARGS...
racer_ms() {
  local bin backend=$2 threads=$3 variantArgs
  bin=$(variant_bin "$1")
  read -ra variantArgs <<< "$(variant_args "$1")"
  shift 3
  local line
  local threadFlag=(--threads "$threads")
  [[ $backend == gl ]] && threadFlag=()  # llvmpipe takes LP_NUM_THREADS; racer refuses --threads with gl
  line=$(LP_NUM_THREADS=$threads "$bin/racer" --headless --content "$CONTENT" --backend "$backend" \
           "${threadFlag[@]}" --fixed-dt 0.0333 "${variantArgs[@]}" "$@" 2>&1 | tee -a "$LOG" | grep 'racer: mean frame') \
    || die "racer ($bin, $backend $*) failed; see $LOG"
  awk '{print $4}' <<< "$line"
}
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2f", a / b}'; }

declare -A t  # t[key] = space-separated samples; key = measure|binary (or |gl)
echo "speed_table: racer frames, $ROUNDS round(s), $THREADS thread(s); log in $LOG" >&2
for round in $(seq "$ROUNDS"); do
  for camera in pan chase; do
    for b in "${bins[@]}"; do
      t[$camera|$b]+=" $(racer_ms "$b" soft "$THREADS" --size 1280x720 --frames 12 --camera "$camera")"
    done
    t[$camera|gl]+=" $(racer_ms new gl "$THREADS" --size 1280x720 --frames 12 --camera "$camera")"
  done
  for b in "${bins[@]}"; do
    t[small|$b]+=" $(racer_ms "$b" soft "$THREADS" --size 160x90 --frames 60 --camera chase)"
    t[one|$b]+=" $(racer_ms "$b" soft 1 --size 1280x720 --frames 12 --camera chase)"
  done
  echo "speed_table: round $round of $ROUNDS done" >&2
done

# ssam-bench: SSAM, SSAM+ and alpha test on both backends (new binary) and on soft (the before
# variant), one scene at a time, the variants alternated scene by scene.
echo "speed_table: ssam-bench tree, forest, vista" >&2
declare -A bench
bench_csv() {  # bench_csv VARIANT DIR BACKENDS SCENE
  local variantArgs
  read -ra variantArgs <<< "$(variant_args "$1")"
  "$(variant_bin "$1")/ssam-bench" --content "$CONTENT" --scenes "$4" --techniques ssam,ssam-plus,alpha-test \
    --backend "$3" --threads "$THREADS" --reps 3 --pan-frames 2 "${variantArgs[@]}" --out "$2" >> "$LOG" 2>&1 \
    || die "ssam-bench ($1) failed; see $LOG"
  # scene,technique,backend -> time_ms_median (column 6)
  awk -F, 'NR > 1 && $6 != "" {print $1 "," $2 "," $3, $6}' "$2/bench.csv"
}
for scene in tree forest vista; do
  if [[ ${#bins[@]} == 2 ]]; then
    while read -r key ms; do bench[$key|${bins[0]}]=$ms; done < <(bench_csv "${bins[0]}" "$OUT/ssam-bench-before/$scene" soft "$scene")
  fi
  while read -r key ms; do bench[$key|new]=$ms; done < <(bench_csv new "$OUT/ssam-bench/$scene" soft,gl "$scene")
done

med() { median <<< "${t[$1]}"; }
# met VALUE GOAL: "yes" or "no", the value's last number (a worst, or ms) against the goal's bound
# ("≤ 0.5 (worst)", "≥ 1.8", "≤ 5 ms").
met() {
  awk -v value="$1" -v goal="$2" 'BEGIN {
    n = split(value, v, /[^0-9.]+/); x = ""; for (i = n; i >= 1 && x == ""; --i) if (v[i] != "") x = v[i];
    split(goal, g, /[^0-9.]+/); bound = (g[1] != "") ? g[1] : g[2];
    ok = index(goal, "≥") ? (x + 0 >= bound + 0) : (x + 0 <= bound + 0);
    print ok ? "yes" : "no" }'
}
row() {  # row MEASURE GOAL VALUE_FOR_BIN... (met: the last binary's, the "after" column)
  local measure=$1 goal=$2; shift 2
  if [[ ${#bins[@]} == 2 ]]; then printf '| %s | %s | %s | %s | %s |\n' "$measure" "$1" "$2" "$goal" "$(met "$2" "$goal")"
  else printf '| %s | %s | %s | %s |\n' "$measure" "$1" "$goal" "$(met "$1" "$goal")"; fi
}
values() {  # values FUNCTION: the function's value for each binary, one line each, in bins order
  local b; for b in "${bins[@]}"; do "$1" "$b"; echo; done
}
pan_ratio() { ratio "$(med "pan|$1")" "$(med pan\|gl)"; }
chase_ratio() { ratio "$(med "chase|$1")" "$(med chase\|gl)"; }
ssam_ratio() {
  local worst=0 scene r
  for scene in tree forest vista; do
    r=$(ratio "${bench[$scene,ssam,soft|$1]}" "${bench[$scene,ssam,gl|new]}")
    worst=$(awk -v a="$worst" -v b="$r" 'BEGIN {print (b > a) ? b : a}')
    printf '%s %s; ' "$scene" "$r"
  done
  printf 'worst %s' "$worst"
}
ssam_over_alpha() { ratio "${bench[forest,ssam,soft|$1]}" "${bench[forest,alpha-test,soft|$1]}"; }
plus_over_ssam() { ratio "${bench[forest,ssam-plus,soft|$1]}" "${bench[forest,ssam,soft|$1]}"; }
small_ms() { printf '%.1f ms' "$(med "small|$1")"; }
speedup() { ratio "$(med "one|$1")" "$(med "chase|$1")"; }

{
  echo
  echo "The soft backend against llvmpipe on this machine ($(nproc) cores; $THREADS thread(s) each: soft --threads, llvmpipe LP_NUM_THREADS)"
  echo
  if [[ ${#bins[@]} == 2 ]]; then
    echo "| measure | before ($(before_label)) | after ($BIN) | goal | met |"; echo "|---|---:|---:|---|---|"
  else
    echo "| measure | $BIN | goal | met |"; echo "|---|---:|---|---|"
  fi
  local_row() { local measure=$1 goal=$2 fn=$3 v; mapfile -t v < <(values "$fn"); row "$measure" "$goal" "${v[@]}"; }
  local_row "racer whole frame 1280x720 pan: soft / llvmpipe" "≤ 0.5" pan_ratio
  local_row "racer whole frame 1280x720 chase: soft / llvmpipe" "≤ 0.5" chase_ratio
  local_row "ssam-bench SSAM frame soft / llvmpipe" "≤ 0.5 (worst)" ssam_ratio
  local_row "forest: SSAM / alpha test on soft" "≤ 1.5" ssam_over_alpha
  local_row "forest: SSAM+ / SSAM on soft" "≤ 1.3" plus_over_ssam
  local_row "racer 160x90 chase frame" "≤ 5 ms" small_ms
  local_row "2 threads / 1 thread (racer 720p chase, speed-up)" "≥ 1.8" speedup
  echo
  echo "ms (median of $ROUNDS): pan soft $(for b in "${bins[@]}"; do printf '%s ' "$(med "pan|$b")"; done)gl $(med pan\|gl);" \
       "chase soft $(for b in "${bins[@]}"; do printf '%s ' "$(med "chase|$b")"; done)gl $(med chase\|gl);" \
       "chase 1 thread $(for b in "${bins[@]}"; do printf '%s ' "$(med "one|$b")"; done)"
} | tee "$OUT/speed_table.md"
# Every ssam-bench median the ratios came from, for the log (the table keeps the ratios).
echo "ssam-bench medians (ms): $(for k in "${!bench[@]}"; do printf '%s=%s ' "$k" "${bench[$k]}"; done | tr ' ' '\n' | sort | tr '\n' ' ')" >> "$LOG"
echo "speed_table: the ssam-bench medians behind the table are at the end of $LOG" >&2

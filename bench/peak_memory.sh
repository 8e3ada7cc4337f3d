#!/usr/bin/env bash
# Peak resident memory of a fresh `selfsim run` expanding dragon level 26, against the size of its output
# vertex array (points × 16 bytes). usage: bench/peak_memory.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
log=$(mktemp)
/usr/bin/time -v "$build/selfsim" run bench/recipes/dragon26.lua -o "$(mktemp -d)" -q >"$log.out" 2>"$log"
points=$(tail -1 "$log.out")
rss_kb=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$log")
wall=$(sed -n 's/.*Elapsed (wall clock) time.*: //p' "$log")
awk -v p="$points" -v r="$rss_kb" -v w="$wall" 'BEGIN {
  a = p * 16 / 1048576; m = r / 1024;
  printf "dragon level 26: %d points, vertex array %.0f MiB, peak RSS %.0f MiB = %.3f x the array (wall %s)\n", p, a, m, m / a, w }'
rm -f "$log" "$log.out"

#!/usr/bin/env bash
# Speed as a user meets it: a whole fresh `selfsim run` of bench/recipes/hoist_million.lua (sampling a
# B-spline, four generations of multiplicity 5, about a million points, written as .vtp), median wall time of
# RUNS runs, with every core and with --threads 1. No peer runs beside it: seed 000's own tool (Java, 2011)
# was never published, and no Debian or npm package hoists curves.
# usage: bench/hoist_run.sh [BUILD_DIR] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
runs=${2:-9}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
selfsim=$(realpath "$build/selfsim")
. bench/wall_time.sh
for flags in "" "--threads 1"; do
  "$selfsim" run bench/recipes/hoist_million.lua -o "$tmp/out" -q $flags  # the first run loads the program
  times=$(for _ in $(seq "$runs"); do wall "$selfsim" run bench/recipes/hoist_million.lua -o "$tmp/out" -q $flags; done)
  m=$(echo "$times" | median)
  printf 'hoist_million %-12s median %.3f s of %s fresh runs (%s), %.1f M points/s\n' "${flags:-all cores}" "$m" "$runs" \
    "$(echo $times | tr '\n' ' ')" "$(echo "1.003126 / $m" | bc -l)"
done

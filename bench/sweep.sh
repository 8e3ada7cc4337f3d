#!/usr/bin/env bash
# A 64-run sweep on this machine against the sum of its runs divided by the jobs (issue 26's goal: at most
# 1.1x). Both sides are whole fresh processes: the sweep (its runs, its contact sheet and series) and the
# same 64 runs one after another with the threads each sweep run gets (cores / jobs).
# usage: bench/sweep.sh [BUILD] [JOBS] [RUNS]
set -euo pipefail
build=${1:-build} jobs=${2:-$(nproc)} runs=${3:-64}
src=$(cd "$(dirname "$0")/.." && pwd)
selfsim=$(cd "$build" && pwd)/selfsim
threads=$(($(nproc) / jobs)); [ "$threads" -ge 1 ] || threads=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/one_by_one.sh" <<SH
for k in \$(seq 1 $runs); do "$selfsim" run "$src/bench/recipes/sweep_curve.lua" -o "$tmp/seq/k=\$k" --set k=\$k --threads $threads -q; done
SH
farm-bench -n 5 --timeout 900 --vs "bash $tmp/one_by_one.sh" -- \
  "$selfsim" run "$src/bench/recipes/sweep_curve.lua" -o "$tmp/sweep" --set "k=1..$runs" --jobs "$jobs" -q
echo "goal: the sweep at most 1.1 / $jobs = $(echo "scale=3; 1.1 / $jobs" | bc) of the one-by-one time"

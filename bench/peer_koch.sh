#!/usr/bin/env bash
# Speed as a user meets it: whole fresh processes. `selfsim run` making the Koch snowflake at n = 11
# (12,582,912 segments, all the way to vertices) beside lindenmayer.js 1.5.4 building the same string in a
# fresh node process. lindenmayer.js is installed from npm into a temporary folder, never into the project.
# Reported two ways:
#   back to back: each tool run RUNS times in a row (caches and the guest's memory warm for that tool);
#   interleaved:  the two tools alternating, as when a user switches between programs (each run then
#                 touches memory the other just gave back, which on a VM can cost more than the work).
# usage: bench/peer_koch.sh [BUILD_DIR] [RUNS]   (extra selfsim flags in SELFSIM_FLAGS, e.g. --threads 1)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
runs=${2:-5}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && npm init -y >/dev/null 2>&1 && npm install --silent --no-audit --no-fund lindenmayer@1.5.4 >/dev/null 2>&1)
cat >"$tmp/koch.mjs" <<'JS'
import LSystem from 'lindenmayer';
const system = new LSystem({ axiom: 'F++F++F', productions: { F: 'F-F++F-F' } });
const s = system.iterate(11);
if (s.length !== 29360128) throw new Error(`unexpected length ${s.length}`);
JS
cat >"$tmp/koch.lua" <<'LUA'
local c = (require "selfsim.curves").koch_snowflake():curve { level = 11 }
assert(c:segments() == 12582912)
LUA
selfsim=$(realpath "$build/selfsim")

. bench/wall_time.sh

run_selfsim >/dev/null; run_node >/dev/null  # first runs load the programs from disk
s_b2b=$(for _ in $(seq "$runs"); do run_selfsim; done | median)
n_b2b=$(for _ in $(seq "$runs"); do run_node; done | median)
s_int=() n_int=()
for _ in $(seq "$runs"); do s_int+=("$(run_selfsim)"); n_int+=("$(run_node)"); done
s_i=$(printf '%s\n' "${s_int[@]}" | median)
n_i=$(printf '%s\n' "${n_int[@]}" | median)
printf 'koch snowflake n=11, median wall seconds of %s fresh processes each\n' "$runs"
printf '  back to back: selfsim %.3f s, lindenmayer.js %.3f s: %.1fx\n' "$s_b2b" "$n_b2b" "$(echo "$n_b2b / $s_b2b" | bc -l)"
printf '  interleaved:  selfsim %.3f s, lindenmayer.js %.3f s: %.1fx\n' "$s_i" "$n_i" "$(echo "$n_i / $s_i" | bc -l)"
printf '  interleaved selfsim runs: %s\n' "${s_int[*]}"

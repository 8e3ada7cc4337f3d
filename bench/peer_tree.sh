#!/usr/bin/env bash
# Speed as a user meets it, parametric rules: `selfsim run bench/recipes/parametric_tree.lua` (the tree at
# level 17, about a million modules, to vertices) beside a fresh node process deriving the same parametric
# system with lindenmayer.js 1.5.4's parametric objects. lindenmayer.js is installed from npm into a
# temporary folder, never into the project. Prints the median wall time of RUNS fresh processes of each,
# run back to back, the ratio, and selfsim's peak memory (GNU time).
# usage: bench/peer_tree.sh [BUILD_DIR] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
runs=${2:-9}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && npm init -y >/dev/null 2>&1 && npm install --silent --no-audit --no-fund lindenmayer@1.5.4 >/dev/null 2>&1)
cat >"$tmp/tree.mjs" <<'JS'
import LSystem from 'lindenmayer';
const system = new LSystem({
  axiom: [{ symbol: 'A', x: 1 }],
  productions: {
    A: ({ part }) => [
      { symbol: 'F', x: part.x }, { symbol: '[' }, { symbol: '+', a: 30 }, { symbol: 'A', x: part.x * 0.5 }, { symbol: ']' },
      { symbol: '[' }, { symbol: '-', a: 30 }, { symbol: 'A', x: part.x * 0.5 }, { symbol: ']' },
    ],
  },
});
const s = system.iterate(17);
if (s.length !== 1048569) throw new Error(`unexpected length ${s.length}`);
JS
selfsim=$(realpath "$build/selfsim")
. bench/wall_time.sh
run_selfsim() { wall "$selfsim" run bench/recipes/parametric_tree.lua -o "$tmp/out" -q; }
run_node() { (cd "$tmp" && wall node tree.mjs); }
run_selfsim >/dev/null; run_node >/dev/null  # first runs load the programs from disk
s=$(for _ in $(seq "$runs"); do run_selfsim; done | median)
n=$(for _ in $(seq "$runs"); do run_node; done | median)
peak=$(/usr/bin/time -f '%M' "$selfsim" run bench/recipes/parametric_tree.lua -o "$tmp/out" -q 2>&1 >/dev/null | tail -1)
printf 'parametric tree level 17, median wall seconds of %s fresh processes each\n' "$runs"
printf '  selfsim %.3f s (peak %s MiB), lindenmayer.js %.3f s: %.1fx\n' "$s" "$((peak / 1024))" "$n" \
  "$(echo "$n / $s" | bc -l)"

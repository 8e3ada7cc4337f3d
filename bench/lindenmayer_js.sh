#!/usr/bin/env bash
# Peer comparison: lindenmayer.js 1.5.4 (npm, MIT) expanding the Koch snowflake string at level N (default
# 10, issue 24's size; 11 was issue 6's) inside node, beside selfsim expanding the same system all the way
# to vertices inside selfsim: both timed in their own process, best of several runs. lindenmayer.js is
# installed into a temporary folder, never into the project. usage: bench/lindenmayer_js.sh [BUILD_DIR] [N]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
level=${2:-10}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && npm init -y >/dev/null 2>&1 && npm install --silent --no-audit --no-fund lindenmayer@1.5.4 >/dev/null 2>&1)
cat >"$tmp/koch.mjs" <<'JS'
import LSystem from 'lindenmayer';
const runs = 5;
let best = Infinity, length = 0;
for (let i = 0; i < runs; i++) {
  const system = new LSystem({ axiom: 'F++F++F', productions: { F: 'F-F++F-F' } });
  const t0 = process.hrtime.bigint();
  const s = system.iterate(Number(process.env.LEVEL));
  const ms = Number(process.hrtime.bigint() - t0) / 1e6;
  length = s.length;
  best = Math.min(best, ms);
}
console.log(`lindenmayer.js koch snowflake n=${process.env.LEVEL}: string of ${length} symbols, best of ${runs}: ${best.toFixed(1)} ms`);
JS
node_line=$(cd "$tmp" && LEVEL=$level node koch.mjs)
selfsim_line=$("$build/selfsim" run bench/recipes/koch_snowflake.lua -o "$tmp/out" -q --set level="$level")
echo "$node_line"
echo "$selfsim_line"
js=$(echo "$node_line" | sed -n 's/.*: \([0-9.]*\) ms$/\1/p')
ss=$(echo "$selfsim_line" | sed -n 's/.*: \([0-9.]*\) ms$/\1/p')
awk -v a="$js" -v b="$ss" 'BEGIN { printf "ratio: selfsim is %.1fx faster (and produces vertices, not just the string)\n", a / b }'

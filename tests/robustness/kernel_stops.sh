#!/usr/bin/env bash
# Long mesh kernels look for a stop per unit of work (issue 21): --timeout inside develop's Loop subdivision,
# thickening (its topology sort and field copies) and self-intersection check ends through the kernel, with
# the recipe line, never through the watchdog a second later ("recipe.lua: stopped: ..." without a line).
# The timeouts fall in different stages of one run (before the fix, 1, 3.8 and 4.6 s ended by the watchdog here); whichever stage each hits, its message names the line.
# usage: kernel_stops.sh SELFSIM SRC
selfsim=$1
src=$2
source "$(dirname "$0")/lib.sh"
cd "$tmp" || exit 1

cat >develop.lua <<'LUA'
local curves = require "selfsim.curves"
local s = develop(curves.dragon(), { levels = 16, smooth = 2, thickness = 0.01 })
print(s)
LUA

for t in 1 2.4 3 3.8 4.6; do
  run_selfsim run develop.lua -o "out$t" -q --timeout "$t"
  if [ "$code" = 0 ]; then continue; fi  # a fast machine finished first: nothing to check
  check "--timeout $t stops inside develop, at its line ($(first_err))" \
    grep -q "^develop.lua:2: develop: stopped: --timeout of $t s reached" "$tmp/err"
done
finish

#!/usr/bin/env bash
# Decomposition and interpretation rules look for a stop as they are counted and as they are written
# (issue 36): --timeout inside a long interpretation ends through the kernel with the recipe line, never
# through the watchdog a second later ("recipe.lua: stopped: ..." without a line). A huge --max-points
# lets each run go on past the timeout: writing through the interpretation (g:count, and g:curve through
# the derivation's own thread), and counting an interpretation whose choices make every module's differ.
# usage: lsystem_stops.sh SELFSIM SRC
selfsim=$1
source "$(dirname "$0")/lib.sh"
cd "$tmp" || exit 1

cat >count.lua <<'LUA'
local g = lsystem { axiom = "A", interpretation = { "A -> F A A" }, max_depth = 40 }
print(g:count(0))
LUA
# Moves make no points, so nothing is held however long it runs.
cat >curve.lua <<'LUA'
local g = lsystem { axiom = "A", interpretation = { "A -> f A A" }, max_depth = 40 }
print(g:curve(0))
LUA
cat >choices.lua <<'LUA'
local g = lsystem { axiom = "A", interpretation = { A = { { 1, "F A A" }, { 1, "F A A" } } }, max_depth = 40 }
print(g:count(0))
LUA

for name in count curve choices; do
  run_selfsim run "$name.lua" -o "out_$name" -q --timeout 2 --max-points 1e12
  check "$name: --timeout stops the interpretation at its line ($(first_err))" \
    grep -q "^$name.lua:2: [a-z]*: stopped: --timeout of 2 s reached" "$tmp/err"
  check "$name: exit 1 (got $code)" test "$code" = 1
done
finish

#!/usr/bin/env bash
# Finalizers at Lua's C-stack limit (issue 21): a recipe that re-enters a kernel from its own options table
# until the C stack overflows makes every finalizer that runs there fail. The error stays one line, and the
# values whose finalizers failed are still released: they no longer count against --max-points.
# usage: finalizers.sh SELFSIM SRC
selfsim=$1
src=$2
source "$(dirname "$0")/lib.sh"
cd "$tmp" || exit 1

cat >deep.lua <<'LUA'
local curves = require "selfsim.curves"
local P = {}
for i = 1, 300 do P[i] = { i, 0, 0 } end
P[301] = { 0, 1, 0 }
local opts
opts = setmetatable({}, { __index = function(t, k)
  if k == "levels" then
    for i = 1, 5 do local m = mesh { points = P, triangles = { { 1, 2, 301 } } } end
    collectgarbage()                 -- the meshes' finalizers run here, at every depth
    return develop(curves.dragon(), opts)
  end
end })
if param("catch", 0) == 0 then develop(curves.dragon(), opts) end
print(pcall(develop, curves.dragon(), opts))
-- Exactly what is left of the budget when every dropped mesh was released.
local pts = {}
for i = 1, 15000 do pts[i] = { i, 0 } end
print(polyline(pts))
LUA

run_selfsim run deep.lua -o out1 -q
check "re-entering develop to the C-stack limit exits 1 (got $code)" [ "$code" = 1 ]
check "and prints one line ($(wc -l <"$tmp/err") lines; first: $(first_err))" [ "$(wc -l <"$tmp/err")" = 1 ]
check "the line names the recipe line ($(first_err))" grep -q "^deep.lua:[0-9]*: C stack overflow" "$tmp/err"

run_selfsim run deep.lua -o out2 -q --set catch=1 --max-points 15100
check "caught, the run goes on (exit $code, $(first_err))" [ "$code" = 0 ]
check "meshes whose finalizers failed hold no points afterwards" grep -q "Curve(15000 points" "$tmp/out"
check "no finalizer warnings ($(first_err))" [ "$(grep -vc "saved nothing" "$tmp/err")" = 0 ]
finish

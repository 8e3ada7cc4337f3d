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

# (The condition keeps g:count from counting it from the rules at once, module_count.h.)
cat >count.lua <<'LUA'
local g = lsystem { axiom = "A(1)", interpretation = { "A(x) : x > 0 -> F A(x) A(x)" }, max_depth = 40 }
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

# A growing level (2^40 A, each drawn as F) whose condition keeps it from being predicted: drawn until the
# timeout, its points growing by copies of hundreds of megabytes, which look for a stop as they copy.
cat >growing.lua <<'LUA'
local g = lsystem { axiom = "A(1)", rules = { "A(x) : x > 0 -> A(x) A(x)" }, interpretation = { "A(x) -> F" },
                    max_depth = 64 }
print(g:curve(40))
LUA
# A decomposition chain (one A becomes 2^16 T as the axiom is written), each T interpreted as 2^16 F.
cat >chain.lua <<'LUA'
local parts, names = { "A(x) : x > 0 -> B(x) B(x)" }, "BCDEGHIJKLMNOPQRT"
for i = 1, 16 do
  local s, t = names:sub(i, i), names:sub(i + 1, i + 1)
  parts[#parts + 1] = s .. "(x) -> " .. t .. "(x)" .. (i < 16 and " " .. t .. "(x)" or "")
end
local looks, shapes = {}, "TUVWXYZabcdeghijF"
for i = 1, 16 do
  local t = shapes:sub(i + 1, i + 1)
  looks[#looks + 1] = shapes:sub(i, i) .. (i == 1 and "(x)" or "") .. " -> " .. t .. " " .. t
end
local g = lsystem { axiom = "A(1)", decomposition = parts, interpretation = looks, max_depth = 64 }
print(g:curve(0))
LUA
for name in growing chain; do
  run_selfsim run "$name.lua" -o "out_$name" -q --timeout 1 --max-points 1e12
  line=$(grep -n "curve(" "$name.lua" | cut -d: -f1)
  check "$name: --timeout stops the drawing at its line ($(first_err))" \
    grep -q "^$name.lua:$line: curve: stopped: --timeout of 1 s reached" "$tmp/err"
  check "$name: exit 1 (got $code)" test "$code" = 1
done
finish

-- Seed 000 from a recipe: splines, hoisting, multiplying, iterating, symmetric control points, simplify.
local h = require "test_helpers"

local pts = { { 0, 0 }, { 0.25, 0.4 }, { 0.6, -0.3 }, { 1, 0 } }
local B, C = bspline { points = pts }, catmull_rom { points = pts }
for _, P in ipairs { B, C } do
  assert(P:paths() == 1 and P:points() > 20, tostring(P))
  assert(P:point(1)[1] == 0 and P:point(1)[2] == 0)
  assert(P:point(P:points())[1] == 1 and P:point(P:points())[2] == 0)
  assert(table.concat(P:fields().points, " ") == "tangent t")
end
-- Finer flatness, more samples.
assert(bspline { points = pts, flatness = 1e-6 }:points() > 4 * B:points())
-- normalize = true maps the ends onto (0,0) and (1,0).
local moved = bspline { points = { { 2, 1 }, { 3, 3 }, { 4, 1 } }, normalize = true }
assert(h.near(moved:point(moved:points())[1], 1))

-- The reference segment hoisted onto P is P (a table of points works as Q).
local on = hoist.onto({ { 0, 0 }, { 1, 0 } }, B)
assert(on:points() == 2 and h.near(on:point(2)[1], 1))
-- A point above the segment's middle lands beside P.
local up = hoist.onto({ { 0.5, 0.1 }, { 0.5, -0.1 } }, B, { boundary = "rotate" })
assert(h.near((up:point(1)[1] + up:point(2)[1]) / 2, up:point(1)[1] / 2 + up:point(2)[1] / 2))

-- MULTIPLY: copies scaled back onto (0,0)-(1,0); a list gives each copy its transform.
local tent = polyline { { 0, 0 }, { 0.5, 0.5 }, { 1, 0 } }
local two = hoist.multiply(tent, 2, { segments = { "identity", "rotate" } })
assert(two:points() == 5 and h.near(two:point(4)[2], -0.25), tostring(two))
local half = hoist.multiply(tent, 2.5)
assert(h.near(half:point(half:points())[1], 1) and h.near(half:point(half:points())[2], 0))

-- ITERATE: (n - 1)·m^g + 1 points, ending at (1,0), with its generation recorded.
local n = B:points()
local it = hoist.iterate(B, { multiplicity = 3, generations = 2, boundary = "rotate", segments = "reflect_y" })
assert(it:points() == (n - 1) * 9 + 1, it:points())
assert(h.near(it:point(it:points())[1], 1, 1e-12))
assert(table.concat(it:fields().points, " ") == "t generation")

-- Symmetric control points from their first half.
local m = hoist.mirror { { 0, 0 }, { 0.2, 0.3 }, { 0.5, 0.4 } }
assert(#m == 5 and m[4][1] == 0.8 and m[4][2] == 0.3 and m[5][1] == 1)
local r = hoist.rotate { { 0, 0 }, { 0.2, 0.3 } }
assert(#r == 4 and r[3][1] == 0.8 and r[3][2] == -0.3)

-- simplify keeps the ends and drops what lies within the tolerance.
local s = simplify(it, 1e-3)
assert(s:points() < it:points() / 4 and s:point(s:points())[1] == it:point(it:points())[1])

save(it, "hoisted.eps")
save(it, "hoisted.vtp")

-- stroke = "none": a filled outline without a line, in both vector formats.
local closed = concat(it, { { 0, 0 } })
save(closed, "filled.svg", { stroke = "none", fill = "gold" })
save(group { { closed, stroke = "none", fill = "gold" } }, "filled.eps")

-- Curve values from the recipe's side: constructors, counts, bbox, points and transform.
local near = require("test_helpers").near

local c = polyline { { 0, 0 }, { 3, 0 }, { 3, 4 } }
assert(c:points() == 3 and c:segments() == 2 and c:paths() == 1)
assert(near(c:length(), 7))
local b = c:bbox()
assert(b.min[1] == 0 and b.min[2] == 0 and b.max[1] == 3 and b.max[2] == 4)

local square = polygon { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } }
assert(square:points() == 5 and near(square:length(), 4), "polygon closes itself")

-- mirror, then scale, then rotate (degrees, counterclockwise), then translate.
local t = c:transform { mirror = true, scale = 2, rotate = 90, translate = { 1, 1 } }
local p = t:point(3) -- (3,4) -> (3,-4) -> (6,-8) -> (8,6) -> (9,7)
assert(near(p[1], 9) and near(p[2], 7), string.format("%g %g", p[1], p[2]))
assert(near(t:length(), 14))
assert(c:point(3)[2] == 4, "transform leaves the original alone")

-- A curve saves and reports where it went.
save(t, "sub/t.svg")

-- g:curve(n) is short for g:curve{ level = n }; g:string and g:count agree with it.
local g = lsystem { axiom = "F", rules = { F = "F+F-F" }, angle = 90 }
assert(g:curve(3):segments() == 27 and g:count(3) == 27)
assert(g:string(1) == "F+F-F")
assert(tostring(g):match("^Grammar") and tostring(c):match("^Curve"))

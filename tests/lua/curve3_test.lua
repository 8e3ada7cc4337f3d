-- 3D curves from recipes: polyline{} with {x, y, z} points, Curve3:transform, and the 3D turtle's values.
local function near(a, b, what) assert(math.abs(a - b) < 1e-12, what .. ": " .. tostring(a) .. " ~= " .. tostring(b)) end

local c = polyline { { 0, 0, 0 }, { 0, 1, 0 }, { 0, 1, 2 } }
assert(tostring(c):find("^Curve3%("), "3D points make a Curve3: " .. tostring(c))
assert(c:points() == 3 and c:segments() == 2)
near(c:length(), 3, "length")
local closed = polygon { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 1 } }
assert(closed:points() == 4, "a polygon repeats its first point")

-- Rotation about an axis, counterclockwise seen from where it points: +y turns to +z about +x.
local r = c:transform { rotate = 90, axis = { 1, 0, 0 } }
local p = r:point(2)
near(p[1], 0, "x") near(p[2], 0, "y") near(p[3], 1, "z")
-- The default axis turns as a 2D curve turns; mirror negates y; then scale, then translate.
local q = c:transform { mirror = true, scale = 2, rotate = 90, translate = { 1, 1, 1 } }:point(2)
near(q[1], 1 + 2, "mirrored, scaled, turned x") near(q[2], 1, "y") near(q[3], 1, "z")
assert(not pcall(function() return c:transform { axis = { 0, 0, 0 } } end), "a zero axis is refused")

-- The 3D turtle: a Curve3 whose level is known, and polygons as a mesh.
local g = lsystem { axiom = "F [ &F ] { . -f . +f . +f . }", angle = 90 }
local t = g:curve { level = 0, normalize = false }
assert(tostring(t):find("^Curve3%("), "a grammar with & draws in 3D")
assert(t:level() == 0)
local leaf = g:polygons { level = 0, normalize = false }
assert(leaf:faces() >= 1, "the polygon is triangulated")

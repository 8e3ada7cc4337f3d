-- Plants stand up (docs/curves.md): a grammar that branches or draws in 3D keeps the turtle's frame and
-- units, heading up from the origin; other open curves are normalised onto (0,0)-(1,0); `normalize`, when
-- given, decides.
local h = require "test_helpers"
local curves = require "selfsim.curves"

local function at(c, i, want, what)
  local p = c:point(i)
  for j = 1, #want do assert(h.near(p[j], want[j], 1e-12), what .. ": point " .. i .. " axis " .. j .. ": " .. p[j]) end
end

-- ABOP Figure 2.6 as examples/lsystem_tree3d.lua draws it, without start_angle or normalize: its trunk
-- (the main axis) runs up +y from the origin and the tree is taller than it is wide or deep.
local tree = lsystem {
  axiom = "A(1, 10)",
  define = { r1 = 0.9, r2 = 0.6, a0 = 45, a2 = 45, d = 137.5, wr = 0.707 },
  rules = {
    "A(l, w) -> !(w) F(l) [ &(a0) B(l*r2, w*wr) ] /(d) A(l*r1, w*wr)",
    "B(l, w) -> !(w) F(l) [ -(a2) $ C(l*r2, w*wr) ] C(l*r1, w*wr)",
    "C(l, w) -> !(w) F(l) [ +(a2) $ B(l*r2, w*wr) ] B(l*r1, w*wr)",
  },
  tropism = { 0, -0.05, 0 },
}
local t = tree:curve(8)
at(t, 1, { 0, 0, 0 }, "tree")
at(t, 2, { 0, 1, 0 }, "tree: the first step heads +y, one unit")
local b = t:bbox()
local dx, dy, dz = b.max[1] - b.min[1], b.max[2] - b.min[2], b.max[3] - b.min[3]
assert(dy > dx and dy > dz, ("tree: y extent %g is not the largest (x %g, z %g)"):format(dy, dx, dz))
local f = t:fields().points
local names = " " .. table.concat(f, " ") .. " "
for _, name in ipairs { "branch_order", "root_distance", "width" } do
  assert(names:find(" " .. name .. " "), "tree: no point field " .. name .. " in" .. names)
end
local lo, hi = t:range("branch_order")
assert(lo == 0 and hi > 2, "tree: branch_order " .. lo .. ".." .. hi)
lo, hi = t:range("width")
assert(h.near(hi, 10), "tree: the trunk's width is its !(10) in unit steps, got " .. hi)

-- A 2D bracketed plant heads up in unit steps; normalize = true maps it as before; a start_angle wins.
local bush = lsystem { axiom = "F", rules = { F = "F[+F]F[-F]F" }, angle = 25.7 }
local c = bush:curve(3)
at(c, 1, { 0, 0 }, "bush")
at(c, 2, { 0, 1 }, "bush")
assert(h.near(c:bbox().max[2], 27), "bush level 3: the main axis is 3^3 unit steps tall")
local n = bush:curve { level = 3, normalize = true }
at(n, 1, { 0, 0 }, "normalised bush")
at(n, n:points(), { 1, 0 }, "normalised bush")  -- the last F ends the main axis
at(lsystem { axiom = "F[+F]F", start_angle = 0 }:curve(0), 2, { 1, 0 }, "start_angle 0")
local kept = bush:curve { level = 1, normalize = false }
at(kept, 2, { 0, 1 }, "normalize = false: as drawn")

-- Unbranched open curves are normalised as before, and carry no plant fields.
local d = curves.dragon():curve(6)
at(d, 1, { 0, 0 }, "dragon")
at(d, d:points(), { 1, 0 }, "dragon")
assert(#d:fields().points == 1, "dragon: only `level`")

-- An empty start_angle list is refused (it would read as "not given").
local ok, err = pcall(lsystem, { axiom = "F", start_angle = {} })
assert(not ok and tostring(err):find("non%-empty list"), tostring(err))

-- One solid from several (issue 40): solids apart are joined exactly (their triangles summed); a rim on a
-- base plate, which meet, become one closed solid on a grid; a cut through a plate makes a hole; an open
-- surface is refused. And a plant's tube on the grid tapers by its `width`: thinner at the tips.
local box = require("test_helpers").box

-- Apart: exact, the triangles of both.
local two = solid.union { box(0, 0, 0, 10, 10, 10), box(20, 0, 0, 30, 10, 10) }
assert(two:faces() == 24, "two boxes apart joined: " .. two:faces() .. " triangles")

-- A rim (a ring tube) on a base plate: they meet, so the grid; one closed solid with the plate's footprint.
local ring = {}
for i = 0, 64 do
  local a = 2 * math.pi * i / 64
  ring[#ring + 1] = { 12 * math.cos(a), 12 * math.sin(a), 2.5 }
end
local rim = solid.tube(polyline(ring), { radius = 1.2, method = "grid", check = false })
local base = box(-15, -15, 0, 15, 15, 3)
local coaster = solid.union { base, rim, voxel = 0.25 }
local r = solid.check(coaster)
assert(r.closed, "the union is closed: " .. r.summary)
assert(math.abs(r.size[1] - 30) < 0.5 and math.abs(r.size[3] - 3.7) < 0.3,
       "the union's size " .. r.size[1] .. " x " .. r.size[2] .. " x " .. r.size[3])

-- A hole through the plate: still closed.
local holed = solid.difference(base, { box(-2, -2, -1, 2, 2, 4), voxel = 0.25 })
assert(solid.check(holed).closed, "the holed plate is closed")

-- Two overlapping boxes in one mesh cross themselves: the union goes to the grid, not "exact (2 disjoint
-- solids)" with the crossing kept.
local a, b = box(0, 0, 0, 10, 10, 10), box(5, 5, 5, 15, 15, 15)
local points, triangles = {}, {}
for i = 1, 8 do points[i], points[8 + i] = a:point(i), b:point(i) end
for _, t in ipairs { { 1, 3, 2 }, { 1, 4, 3 }, { 5, 6, 7 }, { 5, 7, 8 }, { 1, 2, 6 }, { 1, 6, 5 },
                     { 2, 3, 7 }, { 2, 7, 6 }, { 3, 4, 8 }, { 3, 8, 7 }, { 4, 1, 5 }, { 4, 5, 8 } } do
  triangles[#triangles + 1] = t
  triangles[#triangles + 1] = { t[1] + 8, t[2] + 8, t[3] + 8 }
end
local crossed = solid.union { mesh { points = points, triangles = triangles }, box(40, 0, 0, 42, 2, 2), voxel = 0.5 }
local rc = solid.check(crossed)
assert(rc.closed and not rc.crossing, "the union of a solid crossing itself: " .. rc.summary)

-- An open surface is refused, naming it.
local sheet = mesh { points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, triangles = { { 1, 2, 3 } } }
local ok, err = pcall(solid.union, { base, sheet })
assert(not ok and err:find("solid 2 is not closed", 1, true) and err:find("solid.thicken", 1, true), err)

-- A plant whose '!' widths shrink by 0.6 a branching (radius 1.55 mm at the trunk, 0.2 mm at the tips), as a
-- grid tube by width: the tips, which reach out to the sides, stick out past the curve by their own radius,
-- not the trunk's; one radius all along sticks out 1.55 mm each side.
local plant = lsystem {
  axiom = "A(10)",
  rules = { "A(w) -> !(w) F [ +(30) A(w * 0.6) ] [ -(30) A(w * 0.6) ]" },
  angle = 30, start_angle = 90,
}
local c = solid.size(plant:curve(5), 40) -- 40 mm wide; its widths scaled with it: 10 becomes about 62
local tapered = solid.tube(c, { radius = 0.025, by = "width", method = "grid", check = false })
local uniform = solid.tube(c, { radius = 1.55, method = "grid", check = false })
local wide = solid.check(tapered, { voxel = 0.2 }).size[1]
local wide_uniform = solid.check(uniform, { voxel = 0.2 }).size[1]
assert(wide_uniform > 40 + 2 * 1.5, "one radius: " .. wide_uniform .. " mm wide")
assert(wide < 40 + 2 * 0.3, "the tapered plant is " .. wide .. " mm wide: its tips are thicker than 0.3 mm")

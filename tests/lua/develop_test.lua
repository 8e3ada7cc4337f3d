-- develop(): the control mesh of a level stack (seed 002 §2, §3.2) from a grammar or from a list of curves.
local curves = require "selfsim.curves"

-- The dragon's unsmoothed stack touches itself from level 4 on (its curves revisit points): refused,
-- naming the first two triangles that meet, unless check = false keeps it.
local ok, err = pcall(develop, curves.dragon(), { levels = 5 })
assert(not ok and err:find("the surface meets itself: triangle 30 %(level 3, tile 10%) meets triangle 36", 1), err)
assert(pcall(develop, curves.dragon(), { levels = 3 }))
assert(pcall(develop, curves.dragon(), { levels = 5, corner_shift = 0.1 }))
local d = develop(curves.dragon(), { levels = 5, check = false })
-- Points: 2^l + 1 per level; faces: 3 per tile, one tile per segment of levels 0..4.
assert(d:points() == 2 + 3 + 5 + 9 + 17 + 33 and d:faces() == 3 * 31, tostring(d))
assert(table.concat(d:fields().points, " ") == "level")
assert(table.concat(d:fields().cells, " ") == "level tile tile_class")
local box = d:bbox()
assert(box.max[3] == 0 and box.min[3] < -1, box.min[3]) -- level 0 on top, finer levels below

-- The same stack given as curves; a substitution makes the same levels as the L-system.
local tent = polyline { { 0, 0 }, { 0.5, 0.5 }, { 1, 0 } }
local stack = {}
for l = 0, 5 do
  stack[#stack + 1] = substitute { path = { { 0, 0 }, { 1, 0 } }, generator = tent, levels = l,
                                   transforms = { "identity", "half_turn" } }
end
local s = develop(stack, { height = 2, check = false })
assert(s:points() == d:points() and s:faces() == d:faces())
assert(s:bbox().min[3] < 2 * box.min[3] + 1e-9 and s:bbox().min[3] > 2 * box.min[3] - 1e-9)

-- A closed curve's stack is an annulus: every level's end point once.
local k = develop(curves.koch_snowflake(), { levels = 3 })
assert(k:points() == 3 + 12 + 48 + 192, tostring(k))
save(d, "dragon_control.vtp")
save(k, "snowflake_control.obj")

-- Loop subdivision: four triangles for one per step, the topology (a disk) and the stack's top corners kept.
local smooth = develop(curves.dragon(), { levels = 5, smooth = 2 })
assert(smooth:faces() == 16 * d:faces(), smooth:faces())
assert(smooth:point(1)[1] == 0 and smooth:point(1)[2] == 0 and smooth:point(1)[3] == 0)
assert(smooth:point(2)[1] == 1 and smooth:point(2)[3] == 0)
save(smooth, "dragon_smooth.vtp")

-- A thickness makes a closed solid: both sheets, and a rim along the boundary.
local solid = develop(curves.dragon(), { levels = 5, smooth = 1, thickness = 0.05, thickness_rate = 0.8 })
assert(solid:points() % 2 == 0, tostring(solid))
assert(table.concat(solid:fields().points, " ") == "level thickness")
save(solid, "dragon_solid.stl")

-- size scales the whole object (its thickness too): here its largest side becomes 100 (millimetres, say).
local sized = develop(curves.dragon(), { levels = 4, smooth = 1, thickness = 0.05, size = 100 })
local sb = sized:bbox()
local side = math.max(sb.max[1] - sb.min[1], sb.max[2] - sb.min[2], sb.max[3] - sb.min[3])
assert(math.abs(side - 100) < 1e-9, side)
-- size_level: level 0, the unit segment, becomes 80 long.
local by_level = develop(curves.dragon(), { levels = 4, size = 80, size_level = 0, check = false })
assert(math.abs(by_level:point(2)[1] - 80) < 1e-9, by_level:point(2)[1])

-- Tile similarity classes (§4.2): with the paper's construction the dragon's count is 131 from level 9 on;
-- unsmoothed tiles are all similar (mirror images included).
local classes = develop(curves.dragon(), { levels = 9, smooth = 2, corner_shift = 0.1, stencil = "bounded" })
local lo, hi = classes:range("tile_class")
assert(lo == 0 and hi == 130, hi)
assert(select(2, d:range("tile_class")) == 0)
-- The classic stencil gives other shapes near points of valence 7, hence other classes.
assert(select(2, develop(curves.dragon(), { levels = 9, smooth = 2, corner_shift = 0.1 }):range("tile_class")) ~= 130)

-- range: a point field first, or the one asked for; errors name the recipe line.
assert(select(2, classes:range("level")) == 9.0)
assert(select(2, classes:range("level", "cells")) == 8)
local ok2, err2 = pcall(classes.range, classes, "nope")
assert(not ok2 and err2:find("develop_test.lua:%d+: range: the value has no field 'nope'"), err2)
assert(not pcall(classes.range, classes, "level", "faces"))
assert(not pcall(classes.range, classes))

-- Far from the origin the classes are the same: the stack is developed near it and moved back.
local far = {}
for l = 0, 9 do far[#far + 1] = curves.dragon():curve { level = l }:transform { translate = { 1e5, 1e5 } } end
local moved = develop(far, { smooth = 2, corner_shift = 0.1, stencil = "bounded" })
assert(select(2, moved:range("tile_class")) == 130)
assert(math.abs(moved:bbox().min[1] - classes:bbox().min[1] - 1e5) < 1e-6)

-- A snowflake, whose turtle ends a rounding error from its start, is rounded all round.
local flake = curves.koch_snowflake():curve { level = 2 }
local round = flake:rounded { samples = 4 }
local first, last = round:point(1), round:point(round:points())
assert(first[1] == last[1] and first[2] == last[2])
assert(math.abs(first[2]) > 1e-3) -- the start is on an arc, not at the old corner (0, 0)

-- solid.check's numbers are what was measured: a slab the grid resolves reads its thickness; one finer than
-- the grid reads the bound it is known to be under (two voxels), with wall_resolved = false, never the
-- rays' first-step number.
local function slab(t)  -- a closed 20 x 20 mm box t mm thick
  return mesh { points = { { 0, 0, 0 }, { 20, 0, 0 }, { 20, 20, 0 }, { 0, 20, 0 },
                           { 0, 0, t }, { 20, 0, t }, { 20, 20, t }, { 0, 20, t } },
                triangles = { { 1, 3, 2 }, { 1, 4, 3 }, { 5, 6, 7 }, { 5, 7, 8 }, { 1, 2, 6 }, { 1, 6, 5 },
                              { 2, 3, 7 }, { 2, 7, 6 }, { 3, 4, 8 }, { 3, 8, 7 }, { 4, 1, 5 }, { 4, 5, 8 } } }
end

local thick = solid.check(slab(1.0), { profile = "fdm", voxel = 0.1 })
assert(thick.wall_resolved == true, "a 1 mm slab is resolved")
assert(math.abs(thick.thinnest_wall - 1.0) < 0.05, "a 1 mm slab reads " .. thick.thinnest_wall)

local thin = solid.check(slab(0.03), { profile = "fdm", voxel = 0.1 })
assert(thin.wall_resolved == false, "a 0.03 mm slab is finer than a 0.1 mm grid resolves")
assert(math.abs(thin.thinnest_wall - 0.2) < 1e-9, "its reading is the bound, two voxels: " .. thin.thinnest_wall)
assert(not thin.passes)

-- args: --max-points 2000
local m = mesh { points = { {0,0,0}, {100,0,0}, {0,100,0}, {0,0,100} }, triangles = { {1,3,2}, {1,2,4}, {2,3,4}, {1,4,3} } }
local r = solid.check(m, { voxel = 0.4 / 3 })  -- on the distance grid (the default rays need none)
assert(r.passes, r.summary)

-- args: --max-points 1000
-- The rays' tree over the triangles is predicted and checked against --max-points before it is built: over
-- it, the walls are not measured and the report says why (no voxel: exact rays, issue 40).
local m = mesh { points = { {0,0,0}, {100,0,0}, {0,100,0}, {0,0,100} }, triangles = { {1,3,2}, {1,2,4}, {2,3,4}, {1,4,3} } }
local r = solid.check(m)
assert(r.passes, r.summary)

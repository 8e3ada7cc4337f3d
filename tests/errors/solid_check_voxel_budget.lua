-- args: --max-points 2000
local m = mesh { points = { {0,0,0}, {100,0,0}, {0,100,0}, {0,0,100} }, triangles = { {1,3,2}, {1,2,4}, {2,3,4}, {1,4,3} } }
local r = solid.check(m)
assert(r.passes, r.summary)

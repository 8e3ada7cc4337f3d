-- two tetrahedra sharing one vertex: closed, but the shared vertex is not a manifold point
local m = mesh { points = { {0,0,0}, {1,0,0}, {0,1,0}, {0,0,1}, {-1,0,0}, {0,-1,0}, {0,0,-1} },
                 triangles = { {1,3,2}, {1,2,4}, {1,4,3}, {2,3,4}, {1,5,6}, {1,7,5}, {1,6,7}, {5,7,6} } }
local v = volume.mesh(m)

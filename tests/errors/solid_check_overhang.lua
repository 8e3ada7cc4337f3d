local m = mesh { points = { {0,0,0}, {10,0,0}, {0,10,0}, {0,0,10} }, triangles = { {1,3,2}, {1,2,4}, {2,3,4}, {1,4,3} } }
solid.check(m, { overhang = 90 })

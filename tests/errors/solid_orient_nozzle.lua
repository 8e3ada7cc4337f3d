local b = mesh { points = { {0,0,0}, {1,0,0}, {0,1,0}, {0,0,1} }, triangles = { {1,3,2}, {1,2,4}, {2,3,4}, {1,4,3} } }
solid.orient(b, { nozzle = 0 })

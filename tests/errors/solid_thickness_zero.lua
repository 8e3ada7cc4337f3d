local m = mesh { points = { {0,0,0}, {10,0,0}, {0,10,0} }, triangles = { {1,2,3} } }
solid.thicken(m, { thickness = 0 })

mesh { points = { {0,0,0}, {1,0,0}, {0,1,0} }, triangles = { {1, 2, 2.5} } }

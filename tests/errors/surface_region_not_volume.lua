local m = mesh { points = { {0,0,0}, {1,0,0}, {0,1,0} }, triangles = { {1,2,3} } }
exclusion.surface { region = m, start = { {.2,.2,.5}, {.8,.2,.5}, {.5,.8,.5} }, radius = 0.1, levels = 2 }

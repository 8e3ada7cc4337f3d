local box = volume.box { min = {0,0,0}, max = {1,1,1} }
local start = mesh { points = { {.2,.2,.5}, {.8,.2,.5}, {.5,.8,.5} }, triangles = { {1,2,3}, {1,2,3} } }
exclusion.surface { region = box, start = start, radius = 0.05, levels = 2 }

local box = volume.box { min = {0,0,0}, max = {1,1,1} }
local m = mesh { points = { {.2,.2,.5}, {.8,.2,.5}, {.5,.8,.5}, {.2,.2,.6}, {.8,.2,.6}, {.5,.8,.4} }, triangles = { {1,2,3}, {4,5,6} } }
exclusion.surface { region = box, start = m, radius = 0.1, levels = 2 }

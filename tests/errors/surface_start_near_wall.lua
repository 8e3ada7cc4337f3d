-- a start nearer than the radius to the walls and between its surfaces: warned, naming the triangles and gaps
local box = volume.box { min = {0,0,0}, max = {1,1,1} }
local start = mesh { points = { {.2,.2,.5}, {.8,.2,.5}, {.5,.8,.5}, {.2,.2,.52}, {.8,.2,.52}, {.5,.8,.52},
                                {.005,.2,.2}, {.005,.8,.2}, {.005,.5,.8} },
                     triangles = { {1,2,3}, {4,5,6}, {7,8,9} } }
exclusion.surface { region = box, start = start, radius = 0.1, levels = 1 }
error("stop")

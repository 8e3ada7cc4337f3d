-- Two exclusion-radius surfaces (seed 004 in 3D) grown against each other in a box: one start mesh of two
-- triangles far apart. They take turns within each level (triangles in order), and never cross or touch;
-- the `surface` cell field says which is which.
--   selfsim run examples/exclusion_two.lua --set levels=8
local levels = param("levels", 7)
local box = volume.box { min = {0,0,0}, max = {2,1,1} }
local starts = mesh { points = { {.2,.2,.3}, {.8,.2,.3}, {.5,.8,.3}, {1.2,.8,.7}, {1.8,.8,.7}, {1.5,.2,.7} },
                      triangles = { {1,2,3}, {4,5,6} } }
local s, report = exclusion.surface { region = box, start = starts, radius = 0.12, factor = 0.8, levels = levels }
print(string.format("%d triangles in two surfaces, %d points could not move", s:faces(), report.stuck))
save(s, "two_surfaces.vtp")
save(box, "box.vtp")

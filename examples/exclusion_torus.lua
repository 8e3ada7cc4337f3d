-- An exclusion-radius surface (seed 004 in 3D) grown inside a torus read from an STL file, the one
-- examples/torus_region.lua makes. Any closed, non-self-crossing STL, OBJ or PLY mesh works as a region.
--   selfsim run examples/exclusion_torus.lua --set levels=8
local levels = param("levels", 7)
local torus = volume.mesh("torus.stl")
local s, report = exclusion.surface { region = torus, start = { {.8,-.2,0}, {1.2,-.2,0}, {1,.2,0} },
                                      radius = 0.1, factor = 0.8, levels = levels }
print(string.format("%d triangles, %d points could not move", s:faces(), report.stuck))
save(s, "torus_growth.vtp")
save(torus, "torus.vtp")

-- An exclusion surface grown in a sphere, written as its final mesh (series=false) or as a ParaView time
-- series of every level (series=true): what writing the growth costs, in a whole run.
--   selfsim run bench/recipes/surface_series.lua -o /tmp/s -q --set levels=10 --set series=true
local levels = param("levels", 10)
local ball = volume.sphere { center = { 0, 0, 0 }, radius = 1 }
local s = exclusion.surface { region = ball, start = { { -.6, -.4, 0 }, { .6, -.4, 0 }, { 0, .6, 0 } },
                              radius = 0.2, factor = 0.8, levels = levels }
if param("series", false) then
  save(s:levels(), "growth.pvd")
else
  save(s, "surface.vtp")
end

-- Issue 25's print speed: an exclusion surface grown in a sphere, smoothed by `smooth` Loop rounds, sized
-- to 80 mm, thickened on OpenVDB (method = "grid", 1 mm) and checked, as examples/print_surface.lua does
-- without its files. Levels 4 with two rounds: about 1.6 million triangles thickened.
local levels = param("levels", 4)
local sphere = volume.sphere { center = { 0, 0, 0 }, radius = 1 }
local f = exclusion.surface { region = sphere, start = { { -0.6, -0.4, 0 }, { 0.6, -0.4, 0 }, { 0, 0.6, 0 } },
                              radius = 0.2, factor = 0.8, levels = levels }
local steps = param("smooth", 2)
if steps > 0 then f = solid.smooth(f, { steps = steps }) end
f = solid.size(f, 80)
local s = solid.thicken(f, { thickness = 1, method = "grid", check = false })
-- --set check=0: the same run without the check (the yardstick of the check's own time, issue 40).
if param("check", 1) == 1 then
  local report = solid.check(s)
  print(s:faces() .. " triangles; " .. report.summary)
else
  print(s:faces() .. " triangles")
end

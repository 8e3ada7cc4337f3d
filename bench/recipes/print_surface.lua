-- Issue 25's print speed: an exclusion surface grown in a sphere, sized to 80 mm, thickened on OpenVDB
-- (method = "grid", 1 mm) and checked. `levels` sets the size (6: about a million triangles thickened).
local levels = param("levels", 6)
local sphere = volume.sphere { center = { 0, 0, 0 }, radius = 1 }
local f = exclusion.surface { region = sphere, start = { { -0.5, -0.3, 0 }, { 0.5, -0.3, 0 }, { 0, 0.6, 0 } },
                              radius = 0.2, factor = 0.8, levels = levels }
local s = solid.thicken(solid.size(f, 80), { thickness = 1, method = "grid", check = false })
local report = solid.check(s)
print(s:faces() .. " triangles; " .. report.summary)

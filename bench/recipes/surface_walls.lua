-- Walls measured two ways (issue 23): an exclusion surface grown in a sphere or in a CSG region (a sphere
-- less a smaller one cut from its side, plus a box), with walls = "mesh" (the boundary's triangles) or
-- "grid" (the region's distance grid, interpolated). Prints per level moves, stuck and time, then the least
-- clearance of the result's corners from the walls as the grid reads it, and the grid's error bound.
--   selfsim run bench/recipes/surface_walls.lua -o /tmp/w -q --set region=csg --set walls=grid --set levels=8
local shape = param("region", "sphere")
local ball = volume.sphere { center = { 0, 0, 0 }, radius = 1 }
local region = ball
if shape == "csg" then
  region = volume.union { volume.difference { ball, volume.sphere { center = { 0, 0, 1 }, radius = 0.6 } },
                          volume.box { min = { -1.4, -0.3, -0.3 }, max = { -0.5, 0.3, 0.3 } } }
end
local s, report = exclusion.surface { region = region, start = { { -.6, -.4, 0 }, { .6, -.4, 0 }, { 0, .6, 0 } },
                                      radius = 0.2, factor = 0.8, levels = param("levels", 7),
                                      walls = param("walls", "mesh") }
local total = 0
for k, l in ipairs(report.levels) do
  total = total + l.seconds
  print(string.format("%s %s level %d: %d moves, %d stuck, %.0f %%, %.2f s", shape, report.walls, k, l.moves, l.stuck,
                      100 * l.stuck / math.max(1, l.moves), l.seconds))
end
print(string.format("%s %s: %d region triangles, voxel %.4g, growth %.2f s", shape, report.walls,
                    report.region_triangles, report.voxel, total))
save(s, "surface.vtp")

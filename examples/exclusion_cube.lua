-- Seed 004's closing section in 3D: an exclusion-radius surface grown from one triangle inside the unit
-- cube. Every level splits each triangle in four and moves the new edge points as far as they can go while
-- the whole surface keeps the level's radius from itself and from the cube's walls.
--   selfsim run examples/exclusion_cube.lua --set levels=8
-- Open growth.vtp in ParaView coloured by `level` (points or cells), with region.vtp at low opacity.
local levels = param("levels", 7)
local cube = volume.box { min = {0,0,0}, max = {1,1,1} }
local s, report = exclusion.surface { region = cube, start = { {.2,.2,.5}, {.8,.2,.5}, {.5,.8,.5} },
                                      radius = 0.1, factor = 0.8, levels = levels }
for i, l in ipairs(report.levels) do
  print(string.format("level %d: %d triangles, %d of %d points could not move, %.2f s", i, l.triangles, l.stuck,
                      l.moves, l.seconds))
end
save(s, "growth.vtp")
save(s, "growth.stl")
save(cube, "region.vtp")
save(cube, "region.vdb", { voxel = report.voxel })

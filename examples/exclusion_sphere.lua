-- An exclusion-radius surface (seed 004 in 3D) grown from one triangle inside a sphere. The sphere's
-- boundary is an icosphere within a quarter voxel of it; the voxel is half the last level's radius.
--   selfsim run examples/exclusion_sphere.lua --set levels=8
local levels = param("levels", 7)
local ball = volume.sphere { center = {0,0,0}, radius = 1 }
local s, report = exclusion.surface { region = ball, start = { {-.6,-.4,0}, {.6,-.4,0}, {0,.6,0} },
                                      radius = 0.2, factor = 0.8, levels = levels }
print(string.format("%d triangles, %d points could not move, the sphere as %d triangles", s:faces(), report.stuck,
                    report.region_triangles))
save(s, "sphere_growth.vtp")
save(ball:boundary { voxel = report.voxel }, "sphere.vtp")

-- An exclusion-radius surface (Bowyer's 3D extension) grown inside a region read from an OpenVDB level
-- set, as Houdini or Blender hand volumes around. blob.vdb is three overlapping spheres saved by selfsim
-- (volume.union{...} saved as .vdb at voxel 0.06); any float level set works, or a grid named with
-- volume.vdb("file.vdb", { grid = "name" }). Its growth is a ParaView time series, the region drawn
-- see-through around it in out/view.py. `--set walls=grid` measures the walls on the file's own level set
-- (interpolated, within sqrt(3)/2 of its voxel) instead of its meshed surface.
--   selfsim run examples/exclusion_vdb.lua --set levels=7
local levels = param("levels", 6)
local blob = volume.vdb("blob.vdb")
local s, report = exclusion.surface { region = blob, start = { { -.4, -.3, 0 }, { .5, -.3, 0 }, { 0, .4, 0 } },
                                      radius = 0.15, factor = 0.8, levels = levels,
                                      walls = param("walls", "mesh") }
print(string.format("%d triangles, %d points could not move, the region as %d triangles", s:faces(), report.stuck,
                    report.region_triangles))
save(s:levels(), "blob_growth.pvd")
save(blob, "blob.vtp")

-- A snowflake coaster, one solid from two (solid.union): a Koch snowflake plate (solid.relief of the closed
-- curve, `height` mm thick) and a round rim along its outline (a tube on the grid, `rim` mm across, its
-- axis lifted to half the rim's width with Mesh:transform, so the rim stands on the bed, wraps the plate's
-- edge and its sharp tips, and rises above the plate's top). The rim and the plate meet, so the union is
-- made on a grid (`voxel` mm) and printed as one closed solid. Saved as 3MF and STL for a slicer.
--   selfsim run examples/print_coaster.lua
local curves = require "selfsim.curves"
local flake = curves.koch_snowflake():curve { level = param("level", 3) }
flake = solid.size(flake, param("size", 90.0))
local plate = solid.relief(flake, { height = param("height", 2.4), check = false })
local r = param("rim", 3.2) / 2
local rim = solid.tube(flake, { radius = r, method = "grid", check = false })
rim = rim:transform { translate = { 0, 0, r } }
local coaster = solid.union { plate, rim, voxel = param("voxel", 0.25) }
save(coaster, "coaster.3mf")
save(coaster, "coaster.stl")

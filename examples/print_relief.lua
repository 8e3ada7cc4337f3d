-- The Koch snowflake (seed 000's substitution curves, curves.koch_snowflake) as a relief: the closed curve at
-- `level`, scaled to `size` mm, raised `height` mm on a `base` mm rectangular plate reaching `margin` mm
-- beyond the outline's bounding box. Saved as 3MF and STL for a slicer.
--   selfsim run examples/print_relief.lua
local curves = require "selfsim.curves"
local flake = curves.koch_snowflake():curve { level = param("level", 3) }
flake = solid.size(flake, param("size", 60.0))
local relief = solid.relief(flake, { height = param("height", 3.0), base = param("base", 1.5) })
save(relief, "snowflake.3mf")
save(relief, "snowflake.stl")

-- On the bed: a solid as it may come (stood on edge, turned, lifted) put back flat for a printer. The Koch
-- snowflake relief of print_relief.lua is stood up like a medallion and tilted; solid.orient lays it on its
-- largest flat face (the plate's underside) and solid.place (which orient ends with) puts that on z = 0,
-- centred. Each call prints what it did and the overhang before and after.
--   selfsim run examples/print_on_bed.lua
local curves = require "selfsim.curves"
local flake = solid.size(curves.koch_snowflake():curve { level = param("level", 3) }, param("size", 60.0))
local relief = solid.relief(flake, { height = 3.0, base = 1.5, check = false })

-- As it might come from elsewhere: a quarter turn about x, a tilt, and 40 mm up.
local standing = relief:transform { rotate = 90, axis = { 1, 0, 0 } }
standing = standing:transform { rotate = 20, axis = { 0, 1, 1 }, translate = { 10, 0, 40 } }
save(standing, "snowflake_standing.vtp")

local flat = solid.orient(standing, { face = "largest" })  -- on the plate's underside
save(flat, "snowflake_on_bed.3mf")

-- Upside down (on the relief's tops) the plate's rim would overhang: the least overhang finds the plate too.
local upside_down = solid.orient(flat, { rotate = 180, axis = { 1, 0, 0 } })
local least = solid.orient(upside_down, { least = "overhang" })
save(least, "snowflake_least_overhang.stl")

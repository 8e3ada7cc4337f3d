-- Seed 004 (Bowyer, A new fractal curve), Figures 3 and 8's curves as jewellery: an exclusion-radius curve
-- grown from a closed triangle inside a hexagon (first radius 0.15, factor 0.8), scaled to `size` mm and
-- made a closed tube.
--   method = "grid" (the default): every point within `radius` of the curve, meshed on an OpenVDB grid.
--     Any turn works: exclusion curves zigzag by up to 172 degrees between neighbouring points, and the two
--     arms of such a turn merge into one solid. Where they merge the print check finds what a printer
--     would make of it: a thin web between the arms and a narrow notch that fills.
--   method = "rings": mitred rings whose radius shrinks with the `level` point field (radius x
--     taper^level), the start triangle thickest. It refuses turns over 170 degrees and bends tighter than
--     the tube, so only a few levels work (levels = 3, size = 40, radius = 0.4), and its mitres at sharp
--     turns are knife edges the print check finds.
--   selfsim run examples/print_pendant.lua
--   selfsim run examples/print_pendant.lua --set method=rings --set size=40 --set radius=0.4
local levels = param("levels", 3)
local hexagon = {}
for i = 0, 5 do hexagon[#hexagon + 1] = { math.cos(math.pi * i / 3), math.sin(math.pi * i / 3) } end
local c = exclusion.curve { region = polygon(hexagon), start = polygon { {-.4,-.3}, {.4,-.3}, {0,.4} },
                            radius = 0.15, factor = 0.8, levels = levels }
c = solid.size(c, param("size", 60.0))
local method = param("method", "grid")
local options = { radius = param("radius", 0.8), method = method }
if method == "rings" then
  options.sides, options.by, options.taper = param("sides", 16), "level", param("taper", 0.9)
else
  options.voxel = param("voxel", 0.0)   -- the grid's, mm; 0 for a quarter of the radius
end
local pendant = solid.tube(c, options)
save(pendant, "pendant.3mf")
save(pendant, "pendant.vtp")   -- ParaView: the solid (rings also carry radius and level)

-- Seed 004 (Bowyer, A new fractal curve), Figures 3 and 8's curves as jewellery: an exclusion-radius curve
-- grown from a closed triangle inside a hexagon (first radius 0.15, factor 0.8), scaled to `size` mm and
-- swept into a closed tube (a ring, no caps) whose radius shrinks with the `level` point field
-- (radius × taper^level): the start triangle thickest, the newest points thinnest.
-- Only a few levels: exclusion curves zigzag by 150-172 degrees between neighbouring points, and
-- solid.tube's mitred joints refuse turns over 170 degrees or bends tighter than the tube (levels >= 4 at
-- 40 mm with a 0.4 mm radius are refused: "the tube would fold at path 1, point ...").
--   selfsim run examples/print_pendant.lua
local levels = param("levels", 3)
local hexagon = {}
for i = 0, 5 do hexagon[#hexagon + 1] = { math.cos(math.pi * i / 3), math.sin(math.pi * i / 3) } end
local c = exclusion.curve { region = polygon(hexagon), start = polygon { {-.4,-.3}, {.4,-.3}, {0,.4} },
                            radius = 0.15, factor = 0.8, levels = levels }
c = solid.size(c, param("size", 40))
local pendant = solid.tube(c, { radius = param("radius", 0.8), sides = param("sides", 16), by = "level",
                               taper = param("taper", 0.9) })
save(pendant, "pendant.3mf")
save(pendant, "pendant.vtp")   -- ParaView: colour by radius or level

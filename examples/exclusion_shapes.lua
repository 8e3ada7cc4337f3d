-- Seed 004 (Bowyer), Figures 7, 9, 10 and 11: the exclusion-radius curve from other starts and in other
-- regions, and a region with a hole (beyond the paper).
--   Figure 7: an equilateral triangle inside a slightly larger one, factor 0.5: the stable triangles.
--   Figure 9: a square of half the side in the middle of the unit square, filled to show that the curve
--             keeps its inside and outside.
--   Figure 10: an L-shaped region, the start along the centre lines of its two limbs.
--   Figure 11: two start polylines grown against each other, coloured by curve.
--   selfsim run examples/exclusion_shapes.lua --set levels=12
local levels = param("levels", 10)
local square = polygon { {0,0}, {1,0}, {1,1}, {0,1} }

local function triangle(centre, side)
  local pts = {}
  for k = 0, 2 do
    local a = math.rad(90 + 120 * k)
    pts[#pts + 1] = { centre[1] + side / math.sqrt(3) * math.cos(a), centre[2] + side / math.sqrt(3) * math.sin(a) }
  end
  return polygon(pts)
end

local fig7 = exclusion.curve { region = triangle({0, 0}, 1.2), start = triangle({0, 0}, 1),
                               radius = 0.03, factor = 0.5, levels = math.min(levels, 10) }
save({ triangle({0, 0}, 1.2), fig7 }, "figure7.svg", { stroke_width = 1 })

local fig9 = exclusion.curve { region = square, start = polygon { {0.25,0.25}, {0.75,0.25}, {0.75,0.75}, {0.25,0.75} },
                               radius = 0.1, factor = 0.8, levels = levels }
save({ square, { fig9, fill = "#8ecae6" } }, "figure9.svg", { stroke_width = 1 })
save(fig9, "figure9.vtp")

local l_region = polygon { {0,0}, {2,0}, {2,1}, {1,1}, {1,2}, {0,2} }
local fig10 = exclusion.curve { region = l_region, start = polyline { {1.9,0.5}, {0.5,0.5}, {0.5,1.9} },
                                radius = 0.1, factor = 0.8, levels = levels }
save({ l_region, fig10 }, "figure10.svg", { stroke_width = 1 })

local starts = group { polyline { {0.1,0.3}, {0.9,0.3} }, polyline { {0.1,0.7}, {0.5,0.55}, {0.9,0.7} } }
local fig11 = exclusion.curve { region = square, start = starts, radius = 0.1, factor = 0.8, levels = levels }
save({ square, { starts, stroke = "#999999" } }, "figure11_start.svg", { stroke_width = 2 })
save(fig11, "figure11.vtp")  -- colour by the cell field `curve` in ParaView
save({ square, fig11 }, "figure11.svg", { stroke_width = 1 })

-- Beyond the paper: a square region with a round hole, the start around the hole.
local hole = {}
for k = 0, 47 do hole[#hole + 1] = { 0.5 + 0.2 * math.cos(2 * math.pi * k / 48), 0.5 + 0.2 * math.sin(2 * math.pi * k / 48) } end
local holed = group { square, polygon(hole) }
local ring = exclusion.curve { region = holed, start = polygon { {0.15,0.15}, {0.85,0.15}, {0.85,0.85}, {0.15,0.85} },
                              radius = 0.05, factor = 0.8, levels = levels }
save({ square, { ring, fill = "#ffb703" }, { polygon(hole), fill = "white" } }, "hole.svg", { stroke_width = 1 })

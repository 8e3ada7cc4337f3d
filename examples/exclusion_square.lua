-- Seed 004 (Bowyer, A new fractal curve), Figures 3-6: the exclusion-radius curve in the unit square,
-- started on the diagonal from the origin, first exclusion radius 0.1.
--   Figure 3: factor 0.8, 10 levels, breadth first, scanned alternately (bottom left to top right, back).
--   Figure 4: the diagonal and the first five levels of Figure 3, with the exclusion discs of each level's
--             new points (exclusion.discs).
--   Figure 5: as Figure 3 but always scanned forwards: long segments near the origin.
--   Figure 6: factor 0.7, at 10 levels (a) and 11 (b): triangle-shaped voids and how they fill.
-- Each curve's `level` point field says when a point was made; `report.stuck` counts points that could not
-- move from their midpoints.
--   selfsim run examples/exclusion_square.lua --set levels=12
local sheet = require "selfsim.sheet"
local levels = param("levels", 10)
local square = polygon { {0,0}, {1,0}, {1,1}, {0,1} }
local diagonal = polyline { {0,0}, {1,1} }

local function grow(options)
  options.region, options.start, options.radius = square, diagonal, 0.1
  local c, report = exclusion.curve(options)
  return c, report
end

local fig3, report = grow { factor = 0.8, levels = levels }
print(string.format("Figure 3: %d points, %d could not move", fig3:points(), report.stuck))
save({ square, fig3 }, "figure3.svg", { stroke_width = 1 })
save(fig3, "figure3.vtp")

-- Each step with the discs of its newest points: the radius they kept from everything else.
local steps = { group { square, diagonal } }
for l = 1, math.min(5, levels) do
  local c = grow { factor = 0.8, levels = l }
  local discs = exclusion.discs(c, { radius = 0.1, factor = 0.8, level = l })
  steps[#steps + 1] = group { square, { discs, stroke = "#9aa5b1" }, { c, stroke = "#1d3557" } }
end
save(sheet.grid(steps, { columns = 3 }), "figure4.svg", { stroke_width = 1.2 })

local fig5 = grow { factor = 0.8, levels = levels, scan = "forward" }
save({ square, fig5 }, "figure5.svg", { stroke_width = 1 })

local fig6a = grow { factor = 0.7, levels = levels }
local fig6b = grow { factor = 0.7, levels = levels + 1 }
save(sheet.grid({ fig6a, fig6b }, { columns = 2 }), "figure6.svg", { stroke_width = 1 })

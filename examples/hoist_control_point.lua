-- Seed 000 Figure 7: how a self-similar curve changes as one control point of its B-spline moves
-- north-east in equal steps (generations 4, boundary rotate, segments rotate).
local sheet = require "selfsim.sheet"
local steps = param("steps", 5)
local generations = param("generations", 4)

local row = {}
for i = 0, steps - 1 do
  local d = 0.05 * i -- the moving point, third of five
  local P = bspline { points = { { 0, 0 }, { 0.15, 0.3 }, { 0.4 + d, 0.05 + d }, { 0.75, -0.25 }, { 1, 0 } } }
  row[#row + 1] = hoist.iterate(P, { multiplicity = 3, generations = generations,
                                     boundary = "rotate", segments = "rotate" })
end
save(sheet.grid(row, { columns = steps }), "control_point.svg")

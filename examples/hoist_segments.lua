-- Seed 000 Figure 10: the segment modes of MULTIPLY: every copy as is (repeat), every other copy reflected
-- through the y axis (reflect_y), every other copy turned half a circle (rotate). B-spline, generations 3,
-- multiplicity 7, boundary clamp.
local sheet = require "selfsim.sheet"
local generations = param("generations", 3)

local P = bspline { points = { { 0, 0 }, { 0.15, 0.35 }, { 0.55, -0.2 }, { 0.85, 0.15 }, { 1, 0 } } } -- not symmetric: reflect_y shows
local row = {}
for _, mode in ipairs { "repeat", "reflect_y", "rotate" } do
  row[#row + 1] = hoist.iterate(P, { multiplicity = 7, generations = generations,
                                     boundary = "clamp", segments = mode })
end
save(sheet.grid(row, { columns = 3 }), "segments.svg")

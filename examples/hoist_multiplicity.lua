-- Seed 000 Figure 8: the same base curve at different multiplicities. Top row: a B-spline at
-- multiplicities 3, 4, 5, 6 (generations 4, boundary and segments rotate); bottom row: a Catmull-Rom curve
-- at 2, 3, 4, 6 (generations 3, boundary rotate, segments repeat).
local sheet = require "selfsim.sheet"
local detail = param("detail", 0) -- added to every generation count

local B = bspline { points = { { 0, 0 }, { 0.3, 0.35 }, { 0.7, -0.35 }, { 1, 0 } } }
local C = catmull_rom { points = { { 0, 0 }, { 0.25, 0.2 }, { 0.5, 0 }, { 0.75, -0.2 }, { 1, 0 } } }
local cells = {}
for _, m in ipairs { 3, 4, 5, 6 } do
  cells[#cells + 1] = hoist.iterate(B, { multiplicity = m, generations = 4 + detail,
                                         boundary = "rotate", segments = "rotate" })
end
for _, m in ipairs { 2, 3, 4, 6 } do
  cells[#cells + 1] = { hoist.iterate(C, { multiplicity = m, generations = 3 + detail,
                                           boundary = "rotate", segments = "repeat" }), stroke = "#e63946" }
end
save(sheet.grid(cells, { columns = 4 }), "multiplicity.svg")

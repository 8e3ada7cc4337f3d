-- Seed 000 Figure 9: the five boundary modes. The base curve reaches beyond x = 0 and x = 1, so hoisting
-- samples it outside [0, 1] from the first generation on (B-spline, generations 2, multiplicity 2,
-- segments repeat): clamp, repeat, reflect_y, reflect_x, rotate, left to right.
local sheet = require "selfsim.sheet"
local generations = param("generations", 2)

local P = bspline { points = { { 0, 0 }, { -0.25, 0.35 }, { 0.5, 0.45 }, { 1.25, 0.35 }, { 1, 0 } } }
local row = {}
for _, mode in ipairs { "clamp", "repeat", "reflect_y", "reflect_x", "rotate" } do
  row[#row + 1] = hoist.iterate(P, { multiplicity = 2, generations = generations, boundary = mode })
end
save(sheet.grid(row, { columns = 5 }), "boundary.svg")

-- Seed 000 Figure 6: a smooth base curve P, multiplied by three and hoisted onto itself generation after
-- generation (§2.2's ITERATE), on one sheet: P, then generations 1 to 4. The base curve is mirror
-- symmetric (hoist.mirror builds it from its first half, §3.2's editing constraint), so every generation is.
--   selfsim run examples/hoist_generations.lua --set generations=5
local sheet = require "selfsim.sheet"
local generations = param("generations", 4)

local P = bspline { points = hoist.mirror { { 0, 0 }, { 0.2, 0.45 }, { 0.5, -0.15 } } }
local row = { P }
for g = 1, generations do
  row[#row + 1] = hoist.iterate(P, { multiplicity = 3, generations = g, boundary = "rotate" })
end
save(sheet.grid(row, { columns = #row }), "generations.svg", { stroke = { "#999999", "#1d3557" } })
save(row[#row], "generation.vtp") -- point fields t (where along the curve), generation, arclength

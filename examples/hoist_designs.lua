-- Seed 000 Figure 11: self-similar curves as designs, filled with the even-odd rule. Left: a mirror-symmetric
-- B-spline whose base curve overhangs, generation 1, multiplicity 3, boundary rotate, segments repeat.
-- Right: a Catmull-Rom curve symmetric under a half-turn, generations 2, multiplicity 2, boundary clamp,
-- segments rotate. Saved as SVG and as EPS (the seed's own export), and simplified for a plotter.
local sheet = require "selfsim.sheet"
local generations = param("generations", 2)

local A = bspline { points = hoist.mirror { { 0, 0 }, { -0.1, 0.5 }, { 0.3, 0.9 }, { 0.5, 0.3 } } }
local left = hoist.iterate(A, { multiplicity = 3, generations = 1, boundary = "rotate", segments = "repeat" })
local B = catmull_rom { points = hoist.rotate { { 0, 0 }, { 0.1, 0.4 }, { 0.45, 0.35 }, { 0.5, 0 } } }
local right = hoist.iterate(B, { multiplicity = 2, generations = generations, boundary = "clamp", segments = "rotate" })
-- Both end at (1,0): back along the axis to (0,0) makes closed outlines to fill.
left, right = concat(left, { { 0, 0 } }), concat(right, { { 0, 0 } })

local designs = sheet.grid({ { left, fill = "#a8dadc" }, { right, fill = "#f4a261" } }, { columns = 2 })
save(designs, "designs.svg")
save(designs, "designs.eps")
save(simplify(designs, 1e-4), "designs_plotter.svg", { size = "150mm", stroke_width = 0.3 })

-- The gallery `make demo` runs: one result of each part of selfsim, as files ParaView, browsers and
-- slicers open, with the growth of the exclusion curve and surface as ParaView time series. `make demo`
-- then draws a PNG of each (selfsim preview) and the run leaves view.py, the ParaView view of it all:
--   paraview --script=out/view.py
-- selfsim run examples/gallery.lua --set detail=-2   for a quicker, coarser gallery
local curves = require "selfsim.curves"
local detail = param("detail", 0) -- added to every level below

-- L-systems: the classic curves, every level normalised to run from (0,0) to (1,0). SVG only: they are
-- flat drawings, and the 3D results below are what the ParaView view is for.
local function drawing(name, curve) save(curve, name .. ".svg") end
drawing("dragon", curves.dragon():curve { level = 14 + detail })
drawing("terdragon", curves.terdragon():curve { level = 8 + detail })
drawing("hilbert", curves.hilbert():curve { level = 5 + detail })
drawing("arrowhead", curves.arrowhead():curve { level = 7 + detail })
drawing("koch", curves.koch():curve { level = 5 + detail })
drawing("koch_snowflake", curves.koch_snowflake():curve { level = 5 + detail })
drawing("gosper", curves.gosper():curve { level = 4 + detail })
drawing("arrowhead_star", curves.arrowhead_star(5 + detail))
drawing("arrowhead_hexagon", curves.arrowhead_hexagon(5 + detail))

-- A plant: ABOP's Figure 2.6 (Honda's monopodial tree). A grammar that branches keeps the turtle's frame,
-- so the tree stands up along +y from the origin; '!' gives each branch its width (drawn as tubes) and the
-- curve's `branch_order` tells the trunk (0) from its branches.
local tree = lsystem {
  axiom = "A(1, 10)", define = { r1 = 0.9, r2 = 0.6, a0 = 45, a2 = 45, d = 137.5, wr = 0.707 },
  rules = {
    "A(l, w) -> !(w) F(l) [ &(a0) B(l*r2, w*wr) ] /(d) A(l*r1, w*wr)",
    "B(l, w) -> !(w) F(l) [ -(a2) $ C(l*r2, w*wr) ] C(l*r1, w*wr)",
    "C(l, w) -> !(w) F(l) [ +(a2) $ B(l*r2, w*wr) ] B(l*r1, w*wr)",
  },
  tropism = { 0, -0.05, 0 },
}
save(tree:curve(math.max(2, 10 + detail)), "tree.vtp")

-- Kaplan's smooth self-similar curve: a B-spline base curve hoisted onto itself, boundary mode "rotate".
local P = bspline { points = { { 0, 0 }, { -0.25, 0.35 }, { 0.5, 0.45 }, { 1.25, 0.35 }, { 1, 0 } } }
local smooth = hoist.iterate(P, { multiplicity = 2, generations = math.max(1, 4 + detail), boundary = "rotate" })
save(smooth, "hoisted.vtp")

-- Irving & Segerman's developing dragon: the levels stacked at self-similar heights, smoothed by Loop
-- subdivision, its tiles coloured by similarity class (`tile_class`).
local dragon = develop(curves.dragon(), { levels = math.max(2, 9 + detail), smooth = 2, corner_shift = 0.1,
                                          stencil = "bounded" })
local _, classes = dragon:range("tile_class")
print(string.format("developing dragon: %d faces, %d tile classes", dragon:faces(), classes + 1))
save(dragon, "developing_dragon.vtp")

-- Bowyer's Figure 3: the exclusion-radius curve in the unit square, factor 0.8, and its growth.
local square = polygon { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } }
local figure3, report = exclusion.curve { region = square, start = polyline { { 0, 0 }, { 1, 1 } }, radius = 0.1,
                                          factor = 0.8, levels = math.max(1, 10 + detail) }
print(string.format("Figure 3: %d points, %d could not move", figure3:points(), report.stuck))
save({ square, figure3 }, "figure3.svg", { stroke_width = 1 })
save(figure3:levels(), "figure3_growth.pvd")

-- Bowyer's 3D extension: a surface grown from one triangle inside a sphere, never closer to itself or the
-- sphere than a shrinking radius, level by level; and the sphere, drawn see-through in the view.
local ball = volume.sphere { center = { 0, 0, 0 }, radius = 1 }
local surface, grown = exclusion.surface { region = ball, start = { { -.6, -.4, 0 }, { .6, -.4, 0 }, { 0, .6, 0 } },
                                           radius = 0.2, factor = 0.8, levels = math.max(1, 7 + detail) }
print(string.format("exclusion surface: %d triangles, %d points could not move", surface:faces(), grown.stuck))
save(surface:levels(), "surface_growth.pvd")
save(surface, "surface.stl")
save(ball, "sphere.vtp")

-- A recipe made for exploring (README "Exploring"): a smooth self-similar curve (seed 000, hoisted onto
-- itself) whose shape, multiplicity, generations and boundary mode are annotated parameters. Try it in the
-- studio, sweep it, or watch it while you edit:
--   selfsim studio examples/explore.lua
--   selfsim run examples/explore.lua --set height=0.2..0.6:0.1 --set boundary=clamp,rotate
--   selfsim run examples/explore.lua --watch
local height = param("height", 0.45, { min = 0.05, max = 0.8, step = 0.05, doc = "how far the base curve bulges" })
local dip = param("dip", -0.15, { min = -0.6, max = 0.6, step = 0.05, doc = "the height of its middle point" })
local multiplicity = param("multiplicity", 3, { min = 2, max = 5, doc = "copies of the curve along itself" })
local generations = param("generations", 3, { min = 1, max = 5, doc = "times hoisted onto itself" })
local boundary = param("boundary", "rotate", {
  choices = { "clamp", "repeat", "reflect_y", "reflect_x", "rotate" },
  doc = "how the base curve goes on beyond its ends",
})
local colour = param("colour", "#1d3557", { doc = "the stroke of the SVG" })

local P = bspline { points = hoist.mirror { { 0, 0 }, { 0.2, height }, { 0.5, dip } } }
local c = hoist.iterate(P, { multiplicity = multiplicity, generations = generations, boundary = boundary })
save(c, "curve.svg", { stroke = colour })
save(c, "curve.vtp") -- point fields t, generation, arclength: ParaView colours by them

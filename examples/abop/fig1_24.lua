-- ABOP Figure 1.24 a-f: six bracketed plants of the 2D turtle, each drawn at the book's n and delta,
-- side by side in the book's order (a, b, c top row; d, e, f below). `level` draws every plant at that
-- level instead of the book's n (0, the default: the book's). As the book draws them, each plant
-- stands up from the origin in unit steps; the sheet scales each to fit its cell.
--   a  n=5  delta=25.7  F -> F[+F]F[-F]F
--   b  n=5  delta=20    F -> F[+F]F[-F][F]
--   c  n=4  delta=22.5  F -> FF-[-F+F+F]+[+F-F-F]
--   d  n=7  delta=20    X -> F[+X]F[-X]+X,   F -> FF
--   e  n=7  delta=25.7  X -> F[+X][-X]FX,    F -> FF
--   f  n=5  delta=22.5  X -> F-[[X]+X]+F[+FX]-X, F -> FF
--   selfsim run examples/abop/fig1_24.lua
local sheet = require "selfsim.sheet"
local level = param("level", 0, { min = 0, max = 9, doc = "every plant's level; 0: the book's n" })

local figures = {
  { n = 5, angle = 25.7, axiom = "F", rules = { F = "F[+F]F[-F]F" } },
  { n = 5, angle = 20, axiom = "F", rules = { F = "F[+F]F[-F][F]" } },
  { n = 4, angle = 22.5, axiom = "F", rules = { F = "FF-[-F+F+F]+[+F-F-F]" } },
  { n = 7, angle = 20, axiom = "X", rules = { X = "F[+X]F[-X]+X", F = "FF" } },
  { n = 7, angle = 25.7, axiom = "X", rules = { X = "F[+X][-X]FX", F = "FF" } },
  { n = 5, angle = 22.5, axiom = "X", rules = { X = "F-[[X]+X]+F[+FX]-X", F = "FF" } },
}
local plants = {}
for i, f in ipairs(figures) do
  local g = lsystem { axiom = f.axiom, angle = f.angle, rules = f.rules }
  plants[i] = { g:curve(level > 0 and level or f.n), stroke = "#2d6a4f" }
end
local s = sheet.grid(plants, { columns = 3 })
save(s, "fig1_24.svg", { stroke_width = 0.5 })
save(s, "fig1_24.vtp") -- cell field `curve`: which plant (1 = a ... 6 = f)

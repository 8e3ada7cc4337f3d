-- ABOP Figure 1.27: stochastic branching, n = 5, delta = 25.7 (the same angle as Figure 1.24a). Each F
-- becomes one of three branchings, chosen with the book's probabilities 0.33, 0.33 and 0.34:
--   F -(0.33)-> F[+F]F[-F]F    F -(0.33)-> F[+F]F    F -(0.34)-> F[-F]F
-- The book shows several plants of the one grammar; here three seeds stand side by side. A seed always
-- draws the same plant (any --threads), and level n+1 grows from level n. Differs from the book: which
-- plant each seed draws (the book's random numbers are not given).
--   selfsim run examples/abop/fig1_27.lua --set level=5
local sheet = require "selfsim.sheet"
local level = param("level", 5, { min = 0, max = 8, doc = "the level (the book: 5)" })
local plants = {}
for i, seed in ipairs { 1, 2, 3 } do
  local g = lsystem {
    axiom = "F", angle = 25.7, seed = seed,
    rules = { "F -> F[+F]F[-F]F : 0.33", "F -> F[+F]F : 0.33", "F -> F[-F]F : 0.34" },
  }
  plants[i] = { g:curve(level), stroke = "#2d6a4f" }
end
local s = sheet.grid(plants, { columns = 3 })
save(s, "fig1_27.svg", { stroke_width = 0.6 })
save(s, "fig1_27.vtp") -- cell field `curve`: which seed

-- A stochastic bush (ABOP 1.7, Figure 1.27's rules) drawn with three seeds: each F becomes one of three
-- branchings with equal weight. The same seed always draws the same bush, whatever --threads says, and a
-- level grows from the level before (a module's choice follows from the seed and its lineage).
--   selfsim run examples/lsystem_bush.lua --set level=6
local sheet = require "selfsim.sheet"
local level = param("level", 5)

local bushes = {}
for i, seed in ipairs { 1, 2, 3 } do
  local bush = lsystem {
    axiom = "F", angle = 25.7, seed = seed,
    rules = { F = { { 1, "F[+F]F[-F]F" }, { 1, "F[+F]F" }, { 1, "F[-F]F" } } },
  }
  bushes[i] = { bush:curve(level), stroke = "#2d6a4f" } -- upright, in unit steps
end
local s = sheet.grid(bushes, { columns = 3 })
save(s, "lsystem_bush.svg", { stroke_width = 0.6 })
save(s, "lsystem_bush.vtp") -- cell field `curve`: which seed

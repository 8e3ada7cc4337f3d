-- A context-sensitive plant (ABOP 1.8, Figure 1.31a, after Hogeweg and Hesper): the symbols 0 and 1 are
-- states that pass signals along the branches; each rule reads the state on either side, skipping the
-- turtle symbols (ignore = "+-F") and, on the left, completed branches. The turns swap sides each step.
--   selfsim run examples/lsystem_signal.lua --set level=30
local level = param("level", 24)
local plant = lsystem {
  axiom = "F1F1F1", angle = 22.5, ignore = "+-F",
  rules = [[
    0 < 0 > 0 -> 0
    0 < 0 > 1 -> 1[+F1F1]
    0 < 1 > 0 -> 1
    0 < 1 > 1 -> 1
    1 < 0 > 0 -> 0
    1 < 0 > 1 -> 1F1
    1 < 1 > 0 -> 0
    1 < 1 > 1 -> 0
    + -> -
    - -> +
  ]],
}
local c = plant:curve(level) -- a plant: upright, in unit steps
save(c, "lsystem_signal.svg", { stroke = "#1d3557" })
save(c, "lsystem_signal.vtp")

-- A bracketed L-system (Prusinkiewicz & Lindenmayer's plant): branches become separate paths, so in
-- ParaView the cell field `path` tells them apart.
local level = param("level", 5)
local plant = lsystem {
  axiom = "X",
  rules = { X = "F+[[X]-X]-F[-FX]+X", F = "FF" },
  angle = 25, start_angle = 70,
}
local c = plant:curve(level) -- a plant: kept as the turtle draws it, leaning at start_angle
save(c, "plant.vtp")
save(c, "plant.svg", { stroke = "#2d6a4f" })

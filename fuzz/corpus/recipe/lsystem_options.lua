local g = lsystem {
  axiom = "X", rules = { X = "F+[[X]-X]-F[-FX]+X", F = "FF" },
  angle = 25, angles = { A = 45 }, start_angle = { 70, 10 }, shrink = 0.5, draw = "FG", move = "f",
}
local c = g:curve { level = param("level", 3), normalize = false }
print(g, g:count(4), #g:string(2), c, c:points(), c:segments(), c:paths(), c:length(), c:level())
save(c, "plant.svg", { stroke = "#2d6a4f", stroke_width = 2, size = 100, fill = "none" })

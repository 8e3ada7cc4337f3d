local c = lsystem { axiom = "F", rules = { F = "F+F" }, angle = 90 }:curve { level = 3 }
local l = c:level(4)

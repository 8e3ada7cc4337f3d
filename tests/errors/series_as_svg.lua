local c = lsystem { axiom = "F", rules = { F = "F+F" }, angle = 90 }:curve { level = 2 }
save(c:levels(), "growth.svg")

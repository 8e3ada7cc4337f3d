local g = lsystem { axiom = "F", rules = { F = "F+F" } }
g:curve { levle = 3 }

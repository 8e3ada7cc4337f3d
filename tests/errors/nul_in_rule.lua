lsystem { axiom = "F", rules = { F = "F\0+F" } }

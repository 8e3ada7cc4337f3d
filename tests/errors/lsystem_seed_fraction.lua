local g = lsystem { axiom = "F", rules = { F = { { 1, "F[+F]" }, { 1, "FF" } } }, seed = 1.5 }

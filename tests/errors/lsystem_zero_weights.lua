local g = lsystem { axiom = "F", rules = { F = { { 0, "F[+F]" }, { 0, "FF" } } } }

local g = lsystem { axiom = "F", rules = { F = { { 0/0, "F[+F]" }, { 1, "FF" } } } }

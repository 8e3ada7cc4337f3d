local g = lsystem { axiom = "F", rules = { [3] = "FF" } }

local g = lsystem { axiom = "A", rules = { "A -> F’A" } }

local g = lsystem { axiom = "F", rules = { "F (0.33) -> F[+F]F" } }

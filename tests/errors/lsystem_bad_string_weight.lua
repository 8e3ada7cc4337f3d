local g = lsystem { axiom = "F", rules = { "F -> F[+F]F : 0.5", "F -> F[-F]F : much" } }

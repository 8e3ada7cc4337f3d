local g = lsystem { axiom = "F", dimension = 4 }

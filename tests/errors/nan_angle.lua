local g = lsystem { axiom = "F", angle = 0 / 0 }

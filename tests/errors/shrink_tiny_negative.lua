lsystem { axiom = "F", shrink = -1e-200 }

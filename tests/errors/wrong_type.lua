local g = lsystem { axiom = 5 }

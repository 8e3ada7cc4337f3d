local g = lsystem { axiom = "F", anlge = 90 }

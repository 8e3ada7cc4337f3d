local g = lsystem { axiom = "" }

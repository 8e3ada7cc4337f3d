lsystem { axiom = "F", ["angle\nx"] = 1 }

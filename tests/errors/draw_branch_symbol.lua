lsystem { axiom = "F", draw = "F[" }

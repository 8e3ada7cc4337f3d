lsystem { axiom = "F", zeta = 1, alpha = 2, mu = 3 }

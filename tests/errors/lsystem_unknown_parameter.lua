local g = lsystem { axiom = "A(1)", rules = { "A(x) -> F(len)" } }

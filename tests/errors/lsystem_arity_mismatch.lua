local g = lsystem { axiom = "A(1, 2)", rules = { "A(x) -> F(x) A(x / 2)" } }

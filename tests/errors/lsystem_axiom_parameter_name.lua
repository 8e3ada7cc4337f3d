local g = lsystem { axiom = "A(x)", rules = { "A(x) -> F(x)" } }

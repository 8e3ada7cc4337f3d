local g = lsystem { axiom = "A(1)", rules = { "A(x) : x > 1 -> F(x *) A(x / 2)" } }

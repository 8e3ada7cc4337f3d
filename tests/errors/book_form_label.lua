local g = lsystem { axiom = "A(1,10)", rules = { "p1 : A(l,w) : * -> F(l) A(l,w)" } }

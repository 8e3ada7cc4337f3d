local g = lsystem { axiom = "A(4)", rules = { "A(x) -> A(x - 1) F(sqrt(x - 2))" } }
g:curve(4)

local g = lsystem { axiom = "A(2)", rules = { "A(x) -> A(x - 1) F(1 / x)" } }
g:curve(2) -- fine
g:curve(3) -- x reaches 0 at level 3

local g = lsystem { axiom = "A(1)", rules = { "A(x) -> !(x - 2) F A(x + 1)" } }
g:curve(1) -- width -1 at level 1

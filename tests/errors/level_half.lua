local g = lsystem { axiom = "F", rules = { F = "F+F" } }
g:string(2.5)

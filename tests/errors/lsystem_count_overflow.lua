local g = lsystem { axiom = "F", rules = { F = string.rep("F", 100) } }
print(g:count(256))

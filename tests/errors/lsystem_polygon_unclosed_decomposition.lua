-- and in decomposition rules
local g = lsystem { axiom = "A", decomposition = { "A -> F+F+F}" } }
print(g:polygons(0))

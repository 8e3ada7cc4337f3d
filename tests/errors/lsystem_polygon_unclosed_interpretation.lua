-- braces balance in interpretation rules too
local g = lsystem { axiom = "A", interpretation = { "A -> {F+F+F" } }
print(g:polygons(0))

-- a '{' never closed in the axiom is refused, as a '[' is (it drew an empty mesh)
local g = lsystem { axiom = "{F+F+F" }
print(g:polygons(0))

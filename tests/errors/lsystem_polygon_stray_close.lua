-- a '}' with no polygon open is refused, as a stray ']' is
local g = lsystem { axiom = "F+F+F}" }
print(g:polygons(0))

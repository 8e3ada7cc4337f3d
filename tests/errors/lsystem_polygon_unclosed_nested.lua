-- polygons nest (the turtle keeps a stack of them): one of two opened is left open
local g = lsystem { axiom = "A", rules = { A = "{{F+F+F}" } }
print(g:polygons(1))

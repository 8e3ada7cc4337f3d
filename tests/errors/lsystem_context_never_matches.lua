-- exit: 0
local g = lsystem { axiom = "AB", rules = { "C < B -> X", "A -> A" } }
g:curve(2)

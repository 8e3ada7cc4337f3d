-- exit: 0
local g = lsystem { axiom = "A+B", rules = { "+ < B -> X" } }
g:curve(2)

-- args: --timeout 0.3
-- a million turns per rule and nothing drawn: the turtle checks the stop per symbol, not per point
local g = lsystem { axiom = "XXXXXXXX", rules = { X = "X" .. string.rep("+", 1000000) } }
g:curve(256)

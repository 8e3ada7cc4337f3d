-- DEL is named as the caret line shows it, \x7f (the message said \127 over a line showing \x7f)
local g = lsystem { axiom = "A", rules = { "A -> \127(" } }

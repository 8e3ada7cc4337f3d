-- Nothing is drawn, but level 60 would rewrite 2^60 symbols: refused before any work.
local g = lsystem { axiom = "X", rules = { X = "XX" } }
local c = g:curve { level = 60 }

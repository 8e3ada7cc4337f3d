-- args: --max-points 1e7
-- branches opened 300000 deep per level: the saved turtle states are predicted and budgeted like points
lsystem { axiom = "X", rules = { X = string.rep("[", 300000) .. "X" .. string.rep("]", 300000) } }:curve(24)

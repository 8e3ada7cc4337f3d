-- args: --max-points 1e7
-- branches opened and never closed: the saved turtle states are predicted and budgeted like points
lsystem { axiom = "X", rules = { X = "[X[X" } }:curve(24)

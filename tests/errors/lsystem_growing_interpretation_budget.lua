-- args: --max-points 1e6
-- a level that grows (2^40 A, each interpreted as F) is predicted from the rules and refused at once, not
-- drawn up to the budget
local g = lsystem { axiom = "A", rules = { A = "AA" }, interpretation = { "A -> F" }, max_depth = 64 }
g:curve(40)

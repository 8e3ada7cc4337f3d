-- args: --max-points 1e5
-- with choices every module's interpretation differs: counted until it passes the budget, then refused
local g = lsystem { axiom = "A", interpretation = { A = { { 1, "F A A" }, { 1, "F A A A" } } }, max_depth = 40 }
g:curve(0)

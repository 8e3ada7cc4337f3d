-- args: --max-points 1e6
-- g:count derives through the interpretation: 2^64 modules from one A are refused at once, not counted one by one
local g = lsystem { axiom = "F A", interpretation = { "A -> F A A" }, max_depth = 64 }
print(g:count(0))

-- args: --max-points 1e6
-- g:count derives through an interpretation with a condition (not predicted from the rules): 2^64 modules from one A are refused at once, not counted one by one
local g = lsystem { axiom = "F A(1)", interpretation = { "A(x) : x > 0 -> F A(x) A(x)" }, max_depth = 64 }
print(g:count(0))

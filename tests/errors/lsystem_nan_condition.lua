-- a condition that computes a NaN (sqrt(-1) != -1 would hold) is an error naming the rule and the module
local g = lsystem { axiom = "A(2)", rules = { "A(x) : sqrt(x) != -1 -> F A(x - 1)" } }
g:curve(3) -- fine
g:curve(4) -- x is -1 at level 3, and its condition is computed deriving level 4

-- a condition that computes an infinite value (exp(800) > 0 would hold) is an error naming the rule and the module
local g = lsystem { axiom = "A(6)", rules = { "A(x) : exp(100 * x) > 0 -> F A(x + 1)" } }
g:curve(2) -- fine: exp(700) is a large ordinary number
g:curve(3) -- x is 8 at level 2, and its condition is computed deriving level 3

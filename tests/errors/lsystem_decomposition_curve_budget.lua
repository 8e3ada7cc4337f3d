-- args: --max-points 1e6
-- each step's modules are decomposed as they are written: level 1's B is counted before it is held
local g = lsystem { axiom = "C", rules = { "C -> F B" }, decomposition = { "B -> A(1)", "A(x) : x > 0 -> F A(x) A(x)" }, max_depth = 30 }
g:curve(2)

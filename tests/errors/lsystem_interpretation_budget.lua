-- args: --max-points 1e6
-- an interpretation that doubles at every depth (2^30 F from one A) is counted and refused before it is drawn
-- (its condition keeps it from being predicted from the rules alone, module_count.h)
local g = lsystem { axiom = "A(1)", interpretation = { "A(x) : x > 0 -> F A(x) A(x)" }, max_depth = 30 }
g:curve(0)

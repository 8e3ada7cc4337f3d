-- args: --max-points 1e6
-- an interpretation that doubles at every depth (2^30 F from one A) is counted and refused before it is drawn
local g = lsystem { axiom = "A", interpretation = { "A -> F A A" }, max_depth = 30 }
g:curve(0)

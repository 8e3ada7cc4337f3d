-- a decomposition that doubles at every depth is counted before it is held, for g:string as for drawing
local g = lsystem { axiom = "A", decomposition = { "A -> F A A" }, max_depth = 64 }
print(g:string(0))

-- args: --max-points 1e6
-- a decomposition rule that never fires leaves the level predicted: refused at once
local g = lsystem { axiom = "A", rules = { A = "AA" }, decomposition = { "B -> F C" }, interpretation = { "A -> F" },
                    max_depth = 64 }
g:curve(40)

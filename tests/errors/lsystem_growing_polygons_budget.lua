-- args: --max-points 1e6
-- polygons of a growing level through decomposition and interpretation (each B written as two D, each D
-- drawn as a square) are predicted from the rules and refused at once
local g = lsystem { axiom = "A", rules = { A = "AAB" }, decomposition = { "B -> D D" },
                    interpretation = { "D -> { F + F + F + F }" }, max_depth = 64 }
g:polygons(30)

-- ABOP's elasticity e is the length of selfsim's tropism vector: the unknown option says how to write it.
local g = lsystem { axiom = "F", rules = { "F -> F[&F]F" }, angle = 25, dimension = 3, elasticity = 0.22 }

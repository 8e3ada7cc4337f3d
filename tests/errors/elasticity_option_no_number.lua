-- The same hint without a number to show: e stands for it.
local g = lsystem { axiom = "F", rules = { "F -> F[&F]F" }, angle = 25, dimension = 3, elastic = true }

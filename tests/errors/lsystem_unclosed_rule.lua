-- a '[' never closed in a plain rule is refused, as it is in a rule with parameters
local g = lsystem { axiom = "F", rules = { F = "F[+F" } }

-- a '[' never closed in the axiom of a plain grammar is refused, as a stray ']' is
local g = lsystem { axiom = "F[+F", rules = { F = "FF" } }

-- A misspelt DSL function names the closest global (nil_name_hint.h).
local g = lsytem { axiom = "F", rules = { "F -> F+F" }, angle = 90 }

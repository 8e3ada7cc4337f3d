local g = lsystem { axiom = "F", rules = { "ω : F" } }

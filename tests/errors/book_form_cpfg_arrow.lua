local g = lsystem { axiom = "F", rules = { "F --> F" } }

local g = lsystem { axiom = "AB", rules = { "A B -> C" } }

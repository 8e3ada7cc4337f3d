local g = lsystem { axiom = "A(1)", rules = { "A(x) : x -> 1 > 2 -> B" } }

local g = lsystem { axiom = "A", rules = "A -> B\0C\nB -> D" }

local g = lsystem.book { axiom = "F" }

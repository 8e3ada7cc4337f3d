local c = lsystem { axiom = "F]F" }:curve { level = 1 }

-- a 16 MiB option name: no quadratic "did you mean", and the message is cut
lsystem { axiom = "F", [string.rep("a", 1 << 24)] = 1 }

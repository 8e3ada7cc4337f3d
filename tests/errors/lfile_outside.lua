local g = lsystem.load("../lsystem_load/tree.l")

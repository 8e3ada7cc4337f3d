local g = lsystem.load("lfile_no_axiom.l")

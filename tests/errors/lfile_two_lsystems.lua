local g = lsystem.load("lfile_two.l")

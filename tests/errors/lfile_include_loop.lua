local g = lsystem.load("lfile_loop_a.l")

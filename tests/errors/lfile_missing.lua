local g = lsystem.load("lfile_nothere.l")

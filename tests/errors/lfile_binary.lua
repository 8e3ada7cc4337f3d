local g = lsystem.load("lfile_binary.l")

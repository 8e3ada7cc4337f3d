local g = lsystem.load("lfile_surface.l")

local g = lsystem.load("lfile_query.l")

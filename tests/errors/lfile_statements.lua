local g = lsystem.load("lfile_statements.l")

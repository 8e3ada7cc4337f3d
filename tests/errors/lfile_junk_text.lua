local g = lsystem.load("lfile_junk_text.l")

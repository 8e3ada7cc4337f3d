local g = lsystem.load("lfile_open_comment.l")

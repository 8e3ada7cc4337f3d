local g = lsystem.load("lfile_start_block.l")

local g = lsystem.load("lfile_define_chain.l")

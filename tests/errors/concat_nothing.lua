local c = concat()

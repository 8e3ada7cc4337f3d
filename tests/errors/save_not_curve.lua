save(5, "x.vtp")

local factor = param("factor", 0.5, "0 to 1")

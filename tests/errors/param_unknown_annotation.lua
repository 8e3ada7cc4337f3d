local factor = param("factor", 0.5, { maximum = 1 })

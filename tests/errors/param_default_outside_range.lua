local factor = param("factor", 1.5, { min = 0.05, max = 1 })

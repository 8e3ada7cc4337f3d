local factor = param("factor", 0.5, { min = 1, max = 0.05 })

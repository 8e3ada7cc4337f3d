local factor = param("factor", 0.5, { step = 0 })

local doc = param("level", 3, { doc = 3 })

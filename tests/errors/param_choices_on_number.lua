local level = param("level", 4, { choices = { "4", "5" } })

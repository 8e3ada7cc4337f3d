local a = param("level", 4, { min = 1 })
local b = param("level", 5, { min = 1 })

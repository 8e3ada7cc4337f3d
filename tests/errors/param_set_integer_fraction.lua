-- args: --set level=2.5
local level = param("level", 3, { min = 1, max = 8 })

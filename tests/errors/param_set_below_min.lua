-- args: --set level=0
local level = param("level", 3, { min = 1 })

-- args: --set level=1e1
local level = param("level", 3)

-- args: --set level=abc
local level = param("level", 3)

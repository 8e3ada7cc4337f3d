-- args: --set mode=a,,b
-- exit: 2
local level = param("level", 3)
local f = param("factor", 0.5)
local m = param("mode", "a")

-- args: --set level=5..1
-- exit: 2
local level = param("level", 3)
local f = param("factor", 0.5)
local m = param("mode", "a")

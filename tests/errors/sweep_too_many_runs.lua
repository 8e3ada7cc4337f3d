-- args: --set level=1..200 --set factor=1..100
-- exit: 2
local level = param("level", 3)
local f = param("factor", 0.5)
local m = param("mode", "a")

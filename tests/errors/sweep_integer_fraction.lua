-- args: --set level=1..3:0.5
-- exit: 2
local level = param("level", 3)

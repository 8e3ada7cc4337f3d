-- args: --set k=1,01
-- exit: 2
local k = param("k", 3)

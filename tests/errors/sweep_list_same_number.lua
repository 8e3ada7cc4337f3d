-- args: --set x=0,-0
-- exit: 2
local x = param("x", 0.5)

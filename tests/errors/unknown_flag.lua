-- args: --levl 3
-- exit: 2
local x = 1

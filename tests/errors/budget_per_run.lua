-- args: --max-points 1048577
-- the budget counts every live curve: the second of these is refused
local dragon = require("selfsim.curves").dragon()
local a = dragon:curve(20)
local b = dragon:curve(20)

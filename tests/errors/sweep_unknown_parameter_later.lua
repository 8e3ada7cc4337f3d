-- args: --set levle=1..3
-- exit: 2
-- A heavy step before the params: `selfsim params` stops there, and the recipe's text tells that no param()
-- is named 'levle' (before, a warning, then three runs at the default and exit 0).
local curves = require "selfsim.curves"
local c = curves.dragon():curve(4)
local level = param("level", 3)
save(c, "c.svg")

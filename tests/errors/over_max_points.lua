-- args: --max-points 1000
local curves = require "selfsim.curves"
local c = curves.dragon():curve { level = 20 }

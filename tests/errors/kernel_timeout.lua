-- args: --timeout 0.2
local curves = require "selfsim.curves"
local c = curves.dragon():curve { level = 27 }

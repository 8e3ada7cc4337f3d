-- args: --timeout 0.1
local curves = require "selfsim.curves"
local c = curves.dragon():curve { level = 27 }

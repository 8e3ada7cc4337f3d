local curves = require "selfsim.curves"
local c = curves.dragon():curve { level = -1 }

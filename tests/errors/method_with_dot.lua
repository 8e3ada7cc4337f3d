local curves = require "selfsim.curves"
local g = curves.dragon()
local c = g.curve { level = 3 }

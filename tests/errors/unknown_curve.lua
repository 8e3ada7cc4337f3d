local curves = require "selfsim.curves"
local g = curves.dragn()

local curves = require "selfsim.curves"
local s = develop(curves.dragon(), { levels = 3, thickness = -0.1 })

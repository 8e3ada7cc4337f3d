-- args: --max-points 100000
local curves = require "selfsim.curves"
local s = develop(curves.dragon(), { levels = 20 })

-- args: --max-points 200000
local curves = require "selfsim.curves"
local s = develop(curves.dragon(), { levels = 8, smooth = 6 })

local curves = require "selfsim.curves"
local s = develop(curves.hilbert(), { levels = 3 })

local curves = require "selfsim.curves"
local s = develop(curves.dragon(), { levels = 3, size = 100, size_level = 4 })

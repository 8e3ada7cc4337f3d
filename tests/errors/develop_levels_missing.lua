local curves = require "selfsim.curves"
local s = develop(curves.dragon(), { levls = 3 })

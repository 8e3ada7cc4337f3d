-- develop: thickness_rate without a thickness would be ignored; it is refused.
local curves = require "selfsim.curves"
develop(curves.dragon(), { levels = 3, thickness_rate = 0.8 })

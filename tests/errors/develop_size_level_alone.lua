-- develop: size_level without size would be ignored; it is refused.
local curves = require "selfsim.curves"
develop(curves.dragon(), { levels = 3, size_level = 1 })

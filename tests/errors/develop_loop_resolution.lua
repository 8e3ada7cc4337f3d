-- develop: resolution belongs to route 2.
local curves = require "selfsim.curves"
develop(curves.dragon(), { levels = 3, resolution = 8 })

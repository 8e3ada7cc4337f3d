-- develop: option check is a boolean.
local curves = require "selfsim.curves"
develop(curves.dragon(), { levels = 3, check = "no" })

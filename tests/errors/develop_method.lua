-- develop: an unknown route.
local curves = require "selfsim.curves"
develop(curves.dragon(), { levels = 3, method = "nurbs" })

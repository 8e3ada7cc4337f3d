-- develop: route 2 smooths by its Bezier arcs; Loop's smooth is refused with it.
local curves = require "selfsim.curves"
develop(curves.hilbert(), { levels = 3, method = "bezier", smooth = 2 })

-- develop: an unknown stencil name is refused, naming the choices.
local curves = require "selfsim.curves"
develop(curves.dragon(), { levels = 4, smooth = 1, stencil = "butterfly" })

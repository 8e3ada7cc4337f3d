-- develop: a stencil without smooth rounds would be ignored; it is refused.
local curves = require "selfsim.curves"
develop(curves.dragon(), { levels = 3, stencil = "bounded" })

local curves = require "selfsim.curves"
local star = curves.arrowhead_star()

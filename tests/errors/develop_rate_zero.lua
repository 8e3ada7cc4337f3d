-- develop: thickness_rate = 0 is not a rate (leave it out for the curve's own).
local curves = require "selfsim.curves"
develop(curves.dragon(), { levels = 3, smooth = 1, thickness = 0.1, thickness_rate = 0 })

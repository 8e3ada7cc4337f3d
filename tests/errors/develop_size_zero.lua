-- size = 0 given explicitly: outside [1e-9, 1e9] (leaving it out keeps the curve's size).
local curves = require "selfsim.curves"
develop(curves.dragon(), { levels = 3, size = 0 })

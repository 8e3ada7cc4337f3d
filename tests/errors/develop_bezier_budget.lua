-- develop: route 2 predicts its mesh (rows grow with the levels) before building it.
local curves = require "selfsim.curves"
develop(curves.hilbert(), { levels = 7, method = "bezier", resolution = 64 })

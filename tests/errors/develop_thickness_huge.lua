-- Thickness is relative to the surface's size: a million times it is refused (a stack 1e150 across can be
-- thickened by 1e148, tests/unit/print/thicken_test.cpp).
local curves = require "selfsim.curves"
develop(curves.dragon(), { levels = 3, thickness = 1e7 })

local hook = polyline { { 0, 0 }, { -1, 0 }, { -1, -1 }, { 1, -1 }, { 1, 0 } }
local c = hoist.multiply(hook, 1.2000000001)

local c = polyline { { 0, 0 }, { 1, 0 } }
local r = c:revers()

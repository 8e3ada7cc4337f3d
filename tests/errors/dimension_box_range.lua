local c = polyline { {0,0}, {1,0}, {1,1} }
local d = dimension(c, { method = "box", to = 12 })

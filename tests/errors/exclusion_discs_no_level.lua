local c = polyline { {0,0}, {1,1} }
local d = exclusion.discs(c, { radius = 0.1 })

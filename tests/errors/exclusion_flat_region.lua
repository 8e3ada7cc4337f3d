local flat = polygon { {0,0}, {1,0}, {2,0} }
local c = exclusion.curve { region = flat, start = polyline { {0.5,0}, {1,0} }, radius = 0.1, levels = 2 }

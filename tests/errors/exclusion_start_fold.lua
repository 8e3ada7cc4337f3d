local square = polygon { {0,0}, {1,0}, {1,1}, {0,1} }
local c = exclusion.curve { region = square, start = polyline { {0.1,0.1}, {0.9,0.1}, {0.5,0.1} }, radius = 0.1, levels = 2 }

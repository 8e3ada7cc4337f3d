local square = polygon { {0,0}, {1,0}, {1,1}, {0,1} }
local c = exclusion.curve { region = square, start = polyline { {0.2,0.2}, {0.5,0}, {0.8,0.2} }, radius = 0.1, levels = 2 }

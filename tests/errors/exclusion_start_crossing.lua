local square = polygon { {0,0}, {1,0}, {1,1}, {0,1} }
local c = exclusion.curve { region = square, start = polyline { {0.5,0.5}, {1.5,0.5} }, radius = 0.1, levels = 3 }

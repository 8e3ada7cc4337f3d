local bow = polygon { {0,0}, {1,1}, {1,0}, {0,1} }
local c = exclusion.curve { region = bow, start = polyline { {0.1,0.5}, {0.2,0.5} }, radius = 0.1, levels = 3 }

local big = polygon { {-1e308,-1e308}, {1e308,-1e308}, {1e308,1e308}, {-1e308,1e308} }
local c = exclusion.curve { region = big, start = polyline { {0,0}, {1,1} }, radius = 1, levels = 2 }

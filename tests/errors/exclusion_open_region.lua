-- An open polyline as the region: refused, not closed silently with an edge the recipe never drew.
local r = polyline { {0,0}, {1,0}, {1,1}, {0,1} }
exclusion.curve { region = r, start = polyline { {0.2,0.2}, {0.8,0.8} }, radius = 0.1, levels = 2 }

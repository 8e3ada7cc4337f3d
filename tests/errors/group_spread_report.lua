-- exclusion.curve returns the curve and its report: as a table's last entry, Lua keeps both
local square = polygon { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } }
local a = polyline { { 0, 0 }, { 1, 1 } }
local g = group { a, exclusion.curve { region = square, start = a, radius = 0.1, factor = 0.8, levels = 2 } }

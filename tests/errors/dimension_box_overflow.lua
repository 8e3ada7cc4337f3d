-- Box counting of a curve whose extent overflows: refused for its extent, not as an option never set.
local c = polyline { {-1e308, 0}, {1e308, 0}, {1e308, 1e308} }
dimension(c, { method = "box" })

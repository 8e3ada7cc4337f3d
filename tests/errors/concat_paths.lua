local a = polyline { { 0, 0 }, { 1, 0 } }
local c = concat(a, group { a, a })

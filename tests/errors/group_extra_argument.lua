local a = polyline { { 0, 0 }, { 1, 0 } }
local g = group({ a }, { a })

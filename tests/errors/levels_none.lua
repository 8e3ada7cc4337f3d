-- A curve made from points has no levels.
local c = polyline { { 0, 0 }, { 1, 0 } }
local l = c:levels()

-- args: --max-points 1000
-- a table of points is checked against the budget before it is copied
local t = {}
for i = 1, 2000 do t[i] = { i, 0 } end
local c = polyline(t)

local c = polyline { { 0, 0 }, { 1, 2 }, { 3, -1 } }
local t = c:transform { mirror = true, scale = 2, rotate = 30, translate = { 1, 1 } }
local b = t:bbox()
print(b.min[1], b.max[2], t:point(1)[1], t:point(3)[2], tostring(t))
local ok, err = pcall(c.points)
print(ok, err)
ok, err = pcall(function() return c:point(4) end)
save(t, "t.svg")

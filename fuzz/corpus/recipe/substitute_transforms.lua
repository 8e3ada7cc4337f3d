local path = polygon { { 0, 0 }, { 1, 0 }, { 0.5, 0.8 } }
local gen = polyline { { 0, 0 }, { 1 / 3, 0 }, { 0.5, 0.3 }, { 2 / 3, 0 }, { 1, 0 } }
local s = substitute { path = path, generator = gen, levels = 3,
                       transforms = { "identity", "reflect_segment", "reflect_bisector", "half_turn" } }
save(s, "sub/snow.vtp")
print(substitute { path = { { 0, 0 }, { 1, 0 } }, generator = { { 0, 0 }, { 0.5, 0.5 }, { 1, 0 } }, levels = 2 })

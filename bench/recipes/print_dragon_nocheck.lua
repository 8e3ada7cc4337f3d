-- examples/print_dragon.lua without the print check: the yardstick of issue 40's check-speed goal (the
-- dragon print at most 1.5x as long with its check as without). The same develop call with `check = false`,
-- no solid.check and no checked .vtp; dragon.3mf is written the same (with -q, save prints no summary, so
-- nothing checks). Run both at the same level:
--   selfsim run examples/print_dragon.lua --set levels=11 -o /tmp/a -q
--   selfsim run bench/recipes/print_dragon_nocheck.lua --set levels=11 -o /tmp/b -q
local curves = require "selfsim.curves"
local levels = param("levels", 8)
local segment = param("segment", 3.2)
local size = param("size", math.ceil(segment * 2 ^ (levels / 2)))
local top = param("top", 2.5)
local finest = param("finest", 0.85)

local dragon = develop(curves.dragon(), { levels = levels, smooth = param("smooth", 2), corner_shift = 0.2,
                                          height = 0.5, thickness = top / size,
                                          thickness_rate = (finest / top) ^ (1 / levels),
                                          size = size, size_level = 0, check = false })
save(dragon, "dragon.3mf")

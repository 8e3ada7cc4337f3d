-- Seed 002 (Irving & Segerman, Developing fractal curves) §3.1.2 and Figure 14: the developing dragon as a
-- 3D print that passes the fdm print check. Route 1 (Loop, `smooth`), inner corners shifted. The thickness
-- "cheats" as the paper's prints do: it shrinks from `top` mm at level 0 to `finest` mm at the last level,
-- far more slowly than the segments. Level 0 spans `size` mm; by default the size keeps the last level's
-- segments `segment` mm long, so that two finest sheets keep a printable gap (at 1.9 mm segments and 0.85 mm
-- walls the smoothed corners of level 10 fuse). `height` 0.5 halves the stack's height (in segment lengths).
-- Opens in a slicer as dragon.3mf; dragon_checked.vtp carries the check's `wall` and `gap` fields (mm).
--   selfsim run examples/print_dragon.lua                                  -- levels 0..8, about 84 mm tall
--   selfsim run examples/print_dragon.lua --set levels=10                  -- Figure 14's levels, about 103 mm
local curves = require "selfsim.curves"
local levels = param("levels", 8)
local segment = param("segment", 3.2)                          -- mm: the last level's segments
local size = param("size", math.ceil(segment * 2 ^ (levels / 2)))  -- mm spanned by level 0
local top = param("top", 2.5)                                  -- mm thick at level 0
local finest = param("finest", 0.85)                           -- mm thick at the last level (fdm: >= 0.8)

local dragon = develop(curves.dragon(), { levels = levels, smooth = param("smooth", 2), corner_shift = 0.2,
                                          height = 0.5, thickness = top / size,
                                          thickness_rate = (finest / top) ^ (1 / levels),
                                          size = size, size_level = 0 })
local report, checked = solid.check(dragon, { profile = "fdm" })
print(report.summary)
for _, finding in ipairs(report.findings) do print("  " .. finding) end
save(dragon, "dragon.3mf")
save(checked, "dragon_checked.vtp")   -- ParaView: colour by wall (mm)

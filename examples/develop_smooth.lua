-- Seed 002 §3.2, Figures 10 and 18-20: the developing dragon and terdragon by route 1, their control meshes
-- smoothed by Loop subdivision (the four corners of each stack kept, its boundary refined as cubic
-- B-splines), then thickened into closed solids. The render version keeps the self-similar thickness (it
-- shrinks with the segments, §3.1.2); the print version shrinks it more slowly (thickness_rate), as the
-- paper's 3D prints "cheat". In ParaView colour by `level` (a smooth height through the stack after
-- subdivision), `thickness` or `tile`.
--   selfsim run examples/develop_smooth.lua --set levels=11 --set smooth=3
local curves = require "selfsim.curves"
local levels = param("levels", 9)
local smooth = param("smooth", 3)

save(develop(curves.dragon(), { levels = levels, smooth = smooth, thickness = 0.03 }), "dragon_render.vtp")
save(develop(curves.dragon(), { levels = levels, smooth = smooth, thickness = 0.03, thickness_rate = 0.85 }),
     "dragon_print.stl")
save(develop(curves.terdragon(), { levels = math.max(1, levels - 3), smooth = smooth }), "terdragon_surface.obj")

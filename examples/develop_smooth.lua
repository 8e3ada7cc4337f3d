-- Seed 002 §3.2, Figures 10 and 18-20: the developing dragon and terdragon by route 1, their control meshes
-- smoothed by Loop subdivision (the four corners of each stack kept, its boundary refined as cubic
-- B-splines). Not yet thickened: an open surface, for ParaView (colour by `level`, a smooth height through
-- the stack after subdivision, or by `tile`) and for renderers.
--   selfsim run examples/develop_smooth.lua --set levels=11 --set smooth=3
local curves = require "selfsim.curves"
local levels = param("levels", 9)
local smooth = param("smooth", 3)

save(develop(curves.dragon(), { levels = levels, smooth = smooth }), "dragon_surface.vtp")
save(develop(curves.terdragon(), { levels = math.max(1, levels - 3), smooth = smooth }), "terdragon_surface.obj")

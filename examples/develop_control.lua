-- Seed 002 Figure 5: the first levels of the dragon curve stacked at self-similar heights (each gap the
-- segment length of the level above it, so gaps shrink by 1/√2) and joined by the linearly interpolating
-- surface: the control mesh of tiles of three triangles that Loop subdivision later smooths. The terdragon
-- (tiles of four triangles) and the Koch snowflake (closed levels: an annulus) beside it.
--   selfsim run examples/develop_control.lua --set levels=10
-- In ParaView colour the faces by `tile` or `level`. From level 4 on the dragon's and terdragon's curves
-- revisit their own points, so the unsmoothed stack touches itself (§3: "the resulting surface would also
-- self-intersect"): develop refuses such a surface unless told `check = false`, as here, to show it.
-- Smoothing (examples/develop_smooth.lua) or corner_shift separates the touching points.
local curves = require "selfsim.curves"
local levels = param("levels", 6)

save(develop(curves.dragon(), { levels = levels, check = false }), "dragon_control.vtp")
save(develop(curves.terdragon(), { levels = math.max(1, levels - 2), check = false }), "terdragon_control.vtp")
save(develop(curves.koch_snowflake(), { levels = math.max(1, levels - 3), height = 0.5 }), "snowflake_control.obj")

-- Seed 002 Figure 5: the first levels of the dragon curve stacked at self-similar heights (each gap the
-- segment length of the level above it, so gaps shrink by 1/√2) and joined by the linearly interpolating
-- surface: the control mesh of tiles of three triangles that Loop subdivision later smooths. The terdragon
-- (tiles of four triangles) and the Koch snowflake (closed levels: an annulus) beside it.
--   selfsim run examples/develop_control.lua --set levels=10
-- In ParaView colour the faces by `tile` or `level`.
local curves = require "selfsim.curves"
local levels = param("levels", 6)

save(develop(curves.dragon(), { levels = levels }), "dragon_control.vtp")
save(develop(curves.terdragon(), { levels = math.max(1, levels - 2) }), "terdragon_control.vtp")
save(develop(curves.koch_snowflake(), { levels = math.max(1, levels - 3), height = 0.5 }), "snowflake_control.obj")

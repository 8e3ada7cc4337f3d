-- Seed 002 §4.2, Figures 18-22: the renders of developing curves built by Loop subdivision, as the paper
-- built them: each level's inner corners shifted inwards a little (corner_shift) so the stack does not touch
-- itself, Loop's bounded-curvature stencil, and the self-similar ("correct") thickness. In ParaView colour by
-- `tile_class`: tiles of one similarity class share a colour, as in the paper's renders. The class counts
-- stop growing once the stack is deep enough: 131 for the dragon (from level 9), 135 for the terdragon
-- (level 7), 125 for the Koch snowflake (level 7), about 1487 for the Gosper curve (bench/README.md).
--   selfsim run examples/develop_renders.lua                    -- Figure 19's level 13 (and the others)
--   selfsim run examples/develop_renders.lua --set dragon=17 --set smooth=2   -- Figure 18 (13.6 M faces)
local curves = require "selfsim.curves"
local smooth = param("smooth", 3)

local function render(name, grammar, levels, thickness)
  local m = develop(grammar, { levels = levels, smooth = smooth, corner_shift = 0.1, stencil = "bounded",
                              thickness = thickness })
  local _, classes = m:range("tile_class")
  print(string.format("%s, levels 0..%d: %d faces, %d tile classes", name, levels, m:faces(), classes + 1))
  save(m, name .. ".vtp")
end

render("dragon", curves.dragon(), param("dragon", 13), 0.02)           -- Figures 18 (level 17), 19 (13)
render("terdragon", curves.terdragon(), param("terdragon", 8), 0.02)   -- Figure 20 (levels 10 and 8)
render("snowflake", curves.koch_snowflake(), param("snowflake", 6), 0.02)  -- Figure 21 (level 6)
render("gosper", curves.gosper(), param("gosper", 5), 0.02)            -- Figure 22 (level 5)

-- Seed 002 §3.1 and §4.1, Figures 14-17: the 3D-printed developing curves, built by route 2, the direct
-- parameterisation (each level smoothed by Bezier arcs through its segment midpoints, the levels joined by
-- Hermite curves). Route 2 takes any curve: the Hilbert curve's levels do not refine segment by segment, so
-- route 1 (Loop) refuses them. For printing, the thickness "cheats" (§3.1.2): it shrinks exponentially from
-- `top` mm at level 0 to `finest` mm at the last level, far more slowly than the segments do. Level 0 spans
-- `size` mm. Each print is a closed, consistently oriented mesh: open the .stl in a slicer.
--   selfsim run examples/develop_prints.lua
--   selfsim run examples/develop_prints.lua --set dragon=8 --set resolution=2   -- quicker drafts
local curves = require "selfsim.curves"
local size = param("size", 100.0)       -- mm spanned by level 0
local top = param("top", 2.0)           -- mm thick at level 0 (3 folds the arrowhead's sheet: develop warns)
local finest = param("finest", 0.8)   -- mm thick at the finest level
local resolution = param("resolution", 4)

local function print3d(name, grammar, levels)
  local m = develop(grammar, { levels = levels, method = "bezier", resolution = resolution,
                              thickness = top / size, thickness_rate = (finest / top) ^ (1 / levels),
                              size = size, size_level = 0 })
  print(string.format("%s, levels 0..%d: %d faces", name, levels, m:faces()))
  save(m, name .. ".stl")
end

print3d("dragon", curves.dragon(), param("dragon", 10))           -- Figure 14
print3d("terdragon", curves.terdragon(), param("terdragon", 6))   -- Figure 15
print3d("hilbert", curves.hilbert(), param("hilbert", 4))         -- Figure 16
print3d("arrowhead", curves.arrowhead(), param("arrowhead", 6))   -- Figure 17

-- The gallery: every built-in curve of seeds 001-003, as .vtp (ParaView) and .svg (browser).
-- selfsim run examples/gallery.lua --set detail=-2   for a quicker, coarser gallery
local curves = require "selfsim.curves"
local detail = param("detail", 0) -- added to every level below

local function show(name, curve)
  save(curve, name .. ".vtp")
  save(curve, name .. ".svg")
end

show("dragon", curves.dragon():curve { level = 14 + detail })
show("terdragon", curves.terdragon():curve { level = 8 + detail })
show("hilbert", curves.hilbert():curve { level = 5 + detail })
show("arrowhead", curves.arrowhead():curve { level = 7 + detail })
show("koch", curves.koch():curve { level = 5 + detail })
show("koch_snowflake", curves.koch_snowflake():curve { level = 5 + detail })
show("gosper", curves.gosper():curve { level = 4 + detail })
show("arrowhead_star", curves.arrowhead_star(5 + detail))
show("arrowhead_hexagon", curves.arrowhead_hexagon(5 + detail))

-- What a failed print check looks like: seed 002's developing dragon (Irving & Segerman, §3.1.2) as an open
-- surface, scaled to `size` mm and thickened to a constant `thickness` mm, too thin for an fdm printer
-- (walls of two 0.4 mm perimeters, 0.8 mm). solid.thicken warns; the report's findings name the thinnest
-- wall and narrowest gap and where they are; fails_checked.vtp carries the `wall` and `gap` fields (mm):
-- in ParaView colour by wall to see the thin spots.
--   selfsim run examples/print_fails.lua
local curves = require "selfsim.curves"
local sheet = develop(curves.dragon(), { levels = param("levels", 6), smooth = param("smooth", 2),
                                         corner_shift = 0.2 })
sheet = solid.size(sheet, param("size", 60.0))
local thin = solid.thicken(sheet, { thickness = param("thickness", 0.3) })
local report, checked = solid.check(thin, { profile = "fdm" })
print(report.passes and "passes" or "fails:")
for _, finding in ipairs(report.findings) do print("  " .. finding) end
print(string.format("thinnest wall %.2f mm", report.thinnest_wall or -1))
save(thin, "fails.3mf")
save(checked, "fails_checked.vtp")

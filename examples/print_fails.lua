-- What a failed print check looks like, and what it tells you to do: seed 002's developing dragon (Irving &
-- Segerman, §3.1.2) as an open surface, scaled to `size` mm and thickened to a constant `thickness` mm, too
-- thin for an fdm printer (walls of two 0.4 mm perimeters, 0.8 mm). solid.thicken warns; solid.check shares
-- that check (report.reused) and lists each problem with its severity (will fail, may fail, cosmetic) and
-- the change that fixes it, in the recipe's terms ("thicken to 0.8 mm (thickness = 0.8 ...) or scale up
-- 2.9x (solid.size)"); the overhang (supports, not a failure) is a number and a field. fails_checked.vtp
-- carries the `wall`, `gap` (mm) and `overhang` (degrees) fields: in ParaView colour by wall to see the thin
-- spots. The same surface in its own units (a `size` under 5) reads as "probably still in model units".
--   selfsim run examples/print_fails.lua
--   selfsim run examples/print_fails.lua --set size=2.47
local curves = require "selfsim.curves"
local sheet = develop(curves.dragon(), { levels = param("levels", 6), smooth = param("smooth", 2),
                                         corner_shift = 0.2 })
sheet = solid.size(sheet, param("size", 60.0))
local thin = solid.thicken(sheet, { thickness = param("thickness", 0.3) })
local report, checked = solid.check(thin, { profile = "fdm" })
print(report.passes and "passes" or "fails:")
for _, p in ipairs(report.problems) do
  print(string.format("  %s: %s\n    fix: %s", p.severity, p.what, p.fix))
end
print(string.format("thinnest wall %.2f mm, overhang %.0f mm², measured once: %s", report.thinnest_wall or -1,
                    report.overhang, tostring(report.reused)))
save(thin, "fails.3mf")
save(checked, "fails_checked.vtp")

-- Seed 004 (Bowyer, A new fractal curve), its 3D extension: an exclusion-radius surface grown from one
-- triangle inside a sphere, as a print. The mesh is smoothed by `smooth` rounds of Loop subdivision
-- (solid.smooth refuses a smoothed mesh that meets itself: then it is printed unsmoothed), scaled to `size`
-- mm (solid.size), thickened on a grid into a `thickness` mm solid, optionally decimated to `triangles`, and
-- checked (fdm). surface.3mf opens in a slicer; surface_checked.vtp carries the check's `wall` and `gap`
-- fields (mm) for ParaView.
-- Smoothing matters: unsmoothed, the sheet's sharp folds leave slots narrower than a nozzle inside them once
-- thickened (levels 5: gaps at about 2,000 places). OpenVDB's adaptive meshing (`adaptivity` > 0) makes
-- fewer triangles but can make the solid cross itself at such folds: the check says so.
--   selfsim run examples/print_surface.lua                               -- passes, about 40 s
--   selfsim run examples/print_surface.lua --set levels=3 --set smooth=1    -- a quick draft; it stands on
--     a point, which the check says will fail (PrusaSlicer stops at its first layer): solid.orient lays it
--     on a face
local levels = param("levels", 4)
local ball = volume.sphere { center = {0,0,0}, radius = 1 }
local s, grown = exclusion.surface { region = ball, start = { {-.6,-.4,0}, {.6,-.4,0}, {0,.6,0} },
                                     radius = param("radius", 0.2), factor = param("factor", 0.8), levels = levels }
print(string.format("grown: %d triangles, %d points could not move", s:faces(), grown.stuck))
local steps = param("smooth", 2)
if steps > 0 then
  local ok, smoothed = pcall(solid.smooth, s, { steps = steps })
  if ok then s = smoothed else print("not smoothed: " .. tostring(smoothed)) end
end
s = solid.size(s, param("size", 80.0))   -- after smoothing, which shrinks a crumpled surface a little
local solid_surface = solid.thicken(s, { thickness = param("thickness", 1.0), method = "grid",
                                        adaptivity = param("adaptivity", 0.0), check = false })
local triangles = param("triangles", 0)   -- 0: not decimated
if triangles > 0 then solid_surface = solid.decimate(solid_surface, { triangles = triangles }) end
local report, checked = solid.check(solid_surface, { profile = "fdm" })
print(report.summary)
for _, finding in ipairs(report.findings) do print("  " .. finding) end
save(solid_surface, "surface.3mf")
save(checked, "surface_checked.vtp")   -- ParaView: colour by wall or gap (mm)

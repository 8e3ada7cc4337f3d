-- Bench: issue 11's conditions, an exclusion surface from one triangle in the unit cube (radius 0.1, factor
-- 0.8), taken to `levels` levels (10: 1,048,576 triangles), written as .vtp; the per-level report printed.
-- `exclusion` picks the rule ("neighbourhood", the default, or "strict", the rule before issue 23).
local levels = param("levels", 8)
local cube = volume.box { min = {0,0,0}, max = {1,1,1} }
local s, report = exclusion.surface { region = cube, start = { {.2,.2,.5}, {.8,.2,.5}, {.5,.8,.5} },
                                      radius = 0.1, factor = 0.8, levels = levels,
                                      exclusion = param("exclusion", "neighbourhood") }
for l, r in ipairs(report.levels) do
  print(string.format("level %2d: %8d triangles, %7d moves, %7d stuck, %7.3f s", l, r.triangles, r.moves, r.stuck,
                      r.seconds))
end
save(s, "exclusion_surface.vtp")

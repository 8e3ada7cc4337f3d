-- The exclusion surface's stuck points per level (issue 23's measure): one triangle in the unit box,
-- radius 0.1, a given factor; prints per level the points that tried to move, those stuck, their share.
--   selfsim run bench/recipes/surface_stuck.lua -o /tmp/st -q --set factor=0.8 --set levels=9
local factor = param("factor", 0.8)
local box = volume.box { min = { 0, 0, 0 }, max = { 1, 1, 1 } }
local s, report = exclusion.surface { region = box, start = { { .2, .2, .5 }, { .8, .2, .5 }, { .5, .8, .5 } },
                                      radius = 0.1, factor = factor, levels = param("levels", 9) }
for k, l in ipairs(report.levels) do
  print(string.format("factor %.1f level %d: %d moves, %d stuck, %.0f %%, %.2f s", factor, k, l.moves, l.stuck,
                      100 * l.stuck / math.max(1, l.moves), l.seconds))
end

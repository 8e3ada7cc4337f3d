-- The exclusion surface's growth per level (issue 23's measures): one triangle in the unit box, radius 0.1,
-- a given factor and rule; prints per level the points that tried to move, those stuck and their share, the
-- area, the local slope of log2 area against the level (the surface's dimension less 2) and the time, then
-- the slope fitted over levels 3 to the last and each local slope's distance from it.
--   selfsim run bench/recipes/surface_stuck.lua -o /tmp/st -q --set factor=0.8 --set levels=9
--   ... --set exclusion=strict          the rule before issue 23
--   ... --set neighbourhood=4           the neighbourhood in radii along the surface (inf: all of it)
local factor = param("factor", 0.8)
local rule = param("exclusion", "neighbourhood")
local options = { region = volume.box { min = { 0, 0, 0 }, max = { 1, 1, 1 } },
                  start = { { .2, .2, .5 }, { .8, .2, .5 }, { .5, .8, .5 } },
                  radius = 0.1, factor = factor, levels = param("levels", 9), exclusion = rule }
if rule == "neighbourhood" then
  local n = param("neighbourhood", "6")
  options.neighbourhood = n == "inf" and math.huge or tonumber(n)
  options.near = param("near", 0.01)
end
local s, report = exclusion.surface(options)
local area0 = 0.5 * 0.6 * 0.6
local xs, ys = {}, {}
for k, l in ipairs(report.levels) do
  local slope = math.log(l.area / (k > 1 and report.levels[k - 1].area or area0), 2)
  print(string.format("factor %.1f level %d: %d moves, %d stuck, %.0f %%, area %.3f, slope %.3f, %.2f s", factor, k,
                      l.moves, l.stuck, 100 * l.stuck / math.max(1, l.moves), l.area, slope, l.seconds))
  if k >= 3 then xs[#xs + 1], ys[#ys + 1] = k, math.log(l.area, 2) end
end
if #xs >= 3 then  -- least squares over levels 3..n
  local n, sx, sy, sxx, sxy = #xs, 0, 0, 0, 0
  for i = 1, n do sx, sy, sxx, sxy = sx + xs[i], sy + ys[i], sxx + xs[i] ^ 2, sxy + xs[i] * ys[i] end
  local fit = (n * sxy - sx * sy) / (n * sxx - sx * sx)
  local worst = 0
  for i = 2, n do worst = math.max(worst, math.abs(ys[i] - ys[i - 1] - fit)) end
  print(string.format("fitted slope over levels 3-%d: %.3f (dimension %.2f); worst local slope off by %.3f",
                      xs[n], fit, 2 + fit, worst))
end

-- Seed 004 (Bowyer), Figure 8 and the fractal dimension: Figure 3's conditions (unit square, diagonal start,
-- radius 0.1) for reduction factors 0.3 to 0.95, each grown `levels` levels. For each, ln L against
-- ln(2^N / L0) (L0 = sqrt 2) is fitted by least squares: slope d, D = d + 1. The paper reports a mean d of
-- 0.496, standard error 0.002, over factors 0.3, 0.5, 0.6 and 0.7, whose lines are straight and almost
-- indistinguishable; 0.8 and above fall below and bend.
-- Writes figure8_points.csv (every level of every factor), figure8_fit.csv (one row per factor, with the
-- box-counting dimension beside) and figure8.svg (the characteristics, from dark blue at 0.3 to red at 0.95,
-- with the axes through the origin).
--   selfsim run examples/exclusion_dimension.lua --set levels=12
local levels = param("levels", 15)
local square = polygon { {0,0}, {1,0}, {1,1}, {0,1} }
local factors = { 0.3, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95 }
local colours = { "#03045e", "#0077b6", "#00b4d8", "#2a9d8f", "#e9c46a", "#f4a261", "#e63946" }

local points = { { "factor", "level", "ln(2^N/L0)", "ln L" } }
local fits = { { "factor", "slope d", "standard error", "D = d + 1", "box-counting D" } }
local lines = {}
local straight = {}
for i, factor in ipairs(factors) do
  local c = exclusion.curve { region = square, start = polyline { {0,0}, {1,1} }, radius = 0.1, factor = factor,
                              levels = levels }
  local d = dimension(c)
  local box = dimension(c, { method = "box" })
  local xy = {}
  for _, p in ipairs(d.points) do
    points[#points + 1] = { factor, p.step, p.x, p.y }
    xy[#xy + 1] = { p.x, p.y }
  end
  fits[#fits + 1] = { factor, d.slope, d.error, d.dimension, box.dimension }
  lines[#lines + 1] = { polyline(xy), stroke = colours[i] }
  if factor <= 0.7 then straight[#straight + 1] = d.slope end
  print(string.format("factor %.2f: d = %.3f ± %.3f, D = %.3f (box counting: %.3f)", factor, d.slope, d.error,
                      d.dimension, box.dimension))
end

local mean, spread = 0, 0
for _, s in ipairs(straight) do mean = mean + s / #straight end
for _, s in ipairs(straight) do spread = spread + (s - mean) ^ 2 end
local error = math.sqrt(spread / (#straight - 1) / #straight)
print(string.format("factors 0.3-0.7: mean d = %.3f, standard error %.3f (paper: 0.496, 0.002)", mean, error))

save(points, "figure8_points.csv")
save(fits, "figure8_fit.csv")
local top = math.log(2 ^ levels / math.sqrt(2))
lines[#lines + 1] = { polyline { {0, 0}, {top, 0} }, stroke = "#888888" }
lines[#lines + 1] = { polyline { {0, 0}, {0, top * 0.6} }, stroke = "#888888" }
save(lines, "figure8.svg", { stroke_width = 1.5 })

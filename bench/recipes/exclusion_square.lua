-- Bench: seed 004's Figure 3 conditions (unit square, diagonal start, radius 0.1, factor 0.8), taken to
-- `levels` levels (16: 65,536 segments; 20: 1,048,576), written as .vtp; the per-level report printed.
local levels = param("levels", 16)
local square = polygon { {0,0}, {1,0}, {1,1}, {0,1} }
local c, report = exclusion.curve { region = square, start = polyline { {0,0}, {1,1} }, radius = 0.1, factor = 0.8,
                                    levels = levels, exclusion = param("exclusion", "exact") }
for l, r in ipairs(report.levels) do
  print(string.format("level %2d: %8d splits, %6d stuck, %7.3f s", l, r.splits, r.stuck, r.seconds))
end
save(c, "exclusion.vtp")

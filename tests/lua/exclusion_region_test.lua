-- A region drawn by an L-system: the Koch snowflake ends a rounding error from its start at levels 1, 2
-- and 4 (3e-16), and is still a closed region (review of issue 21: refused as an open curve).
local curves = require "selfsim.curves"
for _, level in ipairs { 1, 2, 4 } do
  local flake = curves.koch_snowflake():curve { level = level }
  local c, report = exclusion.curve { region = flake, start = polyline { { 0.3, 0.2 }, { 0.7, 0.3 } },
                                      radius = 0.05, levels = 3 }
  assert(c:segments() == 8, "level " .. level .. ": " .. tostring(c))
  assert(report.levels[3].splits == 4)
end

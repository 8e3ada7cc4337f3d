-- The lindenmayer.js comparison: the Koch snowflake expanded to vertices, timed inside selfsim.
local curves = require "selfsim.curves"
local n = param("level", 11)
local g = curves.koch_snowflake()
local runs, best = param("runs", 10), math.huge
local c
for _ = 1, runs do
  local t0 = os.clock()
  c = g:curve { level = n }
  best = math.min(best, os.clock() - t0)
end
print(string.format("selfsim koch snowflake n=%d: %d vertices, best of %d: %.1f ms", n, c:points(), runs, best * 1000))

-- args: --max-points 1000000
local curves = require "selfsim.curves"
local s = develop(curves.koch_snowflake(), { levels = 8, smooth = 4 })

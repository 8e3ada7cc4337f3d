-- One run of a sweep benchmark (bench/sweep.sh): a dragon curve of about 0.1 s, saved as .svg and .vtp.
-- `k` only names the run; `level` sets its size.
local curves = require "selfsim.curves"
local k = param("k", 1, { min = 1 })
local c = curves.dragon():curve(param("level", 18, { min = 1, max = 22 }))
save(c, "c.svg")
save(c, "c.vtp")

-- Peak memory of a level-26 dragon (67,108,864 segments) in a fresh selfsim process; nothing is saved.
local curves = require "selfsim.curves"
local c = curves.dragon():curve { level = param("level", 26) }
print(c:points())

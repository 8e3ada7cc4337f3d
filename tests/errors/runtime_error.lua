local curves = require "selfsim.curves"
local c = curves.dragon():curve { level = 3 }
print(nope(c))

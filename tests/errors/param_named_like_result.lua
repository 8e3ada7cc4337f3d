result("x", 2)
local x = param("x", 1)

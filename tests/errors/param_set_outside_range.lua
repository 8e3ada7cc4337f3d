-- args: --set factor=1.5
local factor = param("factor", 0.8, { min = 0.05, max = 1 })

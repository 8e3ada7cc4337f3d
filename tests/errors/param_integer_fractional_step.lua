-- an integer parameter with a fractional step: the studio control would offer 2.5
local level = param("level", 3, { min = 1, max = 5, step = 0.5 })

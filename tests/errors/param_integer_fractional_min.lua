-- an integer parameter (default written whole) with a fractional bound: the studio control would offer 1.5
local level = param("level", 3, { min = 0.5, max = 5 })

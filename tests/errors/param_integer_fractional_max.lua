-- an integer parameter with a fractional max
local level = param("level", 3, { max = 7.5 })

-- an integer parameter with a whole max beyond what an integer holds
local level = param("level", 3, { max = 1e19 })

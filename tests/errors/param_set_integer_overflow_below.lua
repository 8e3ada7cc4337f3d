-- args: --set level=-99999999999999999999
-- too large below, with only a max declared: the integer range is what it is outside
local level = param("level", 3, { max = 8 })

-- args: --set level=99999999999999999999
-- a whole number too large for an integer, where a range is declared, is outside that range
local level = param("level", 3, { min = 1, max = 8 })

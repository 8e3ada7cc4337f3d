-- args: --set level=99999999999999999999
-- a whole number too large for an integer is out of range, not a fraction
local level = param("level", 3)

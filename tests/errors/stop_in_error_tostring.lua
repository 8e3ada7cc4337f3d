-- args: --timeout 0.3
-- a __tostring that loops while the error is reported: the stop is what is reported
error(setmetatable({}, { __tostring = function() while true do end end }))

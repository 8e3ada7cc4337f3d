error(setmetatable({}, { __tostring = function() return "multi\nline\0nul" end }))

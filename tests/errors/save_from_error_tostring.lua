-- the recipe has failed once its error is being reported: a __tostring cannot save
local c = polyline { { 0, 0 }, { 1, 0 } }
error(setmetatable({}, { __tostring = function() save(c, "after_error.svg") return "boom" end }))

-- args: --timeout 0.3
-- the finalizer only runs when the state closes, after the recipe has returned
setmetatable({}, { __gc = function() while true do end end })

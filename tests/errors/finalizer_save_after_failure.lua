-- a finalizer that runs after the recipe failed cannot write (the local keeps the table alive until then:
-- a garbage collection during the recipe could otherwise run the finalizer early, where saving is allowed)
local keep = setmetatable({}, { __gc = function() save(polyline { { 0, 0 }, { 1, 0 } }, "late.svg") end })
error("boom")

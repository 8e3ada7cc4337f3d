-- args: --timeout 0.1
-- about a billion symbols to walk for a million points ('[]' keeps the precomputed blocks out): the stop
-- comes from inside the kernel, whatever the machine's speed
local g = lsystem { axiom = "X", rules = { X = "X[]" .. string.rep("+-", 500) .. "FX" } }
local c = g:curve { level = 20 }

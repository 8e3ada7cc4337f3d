local function f() return tostring(setmetatable({}, { __tostring = f })) end
f()

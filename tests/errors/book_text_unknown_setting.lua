local g = lsystem.book [[
ω : F
n = 5, k = 3
]]

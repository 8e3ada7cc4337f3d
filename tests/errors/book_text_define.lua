local g = lsystem.book [[
#define r1 0.9 +
ω : F
]]

local g = lsystem.book [[
ω : F
p1 : F → F[+F
]]

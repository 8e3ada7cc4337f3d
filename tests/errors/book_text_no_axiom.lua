local g = lsystem.book [[
p1 : F → F[+F]F
]]

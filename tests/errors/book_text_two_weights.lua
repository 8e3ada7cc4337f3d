local g = lsystem.book [[
ω : F
F (0.5) → F[+F]F : 0.5
]]

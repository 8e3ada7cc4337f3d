local g = lsystem.book([[
ω : F
δ = 22.5°
]], { angle = 30 })

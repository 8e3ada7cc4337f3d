-- radius * taper^width underflows to nothing: it said "the voxel size 2.5e-301 is too small", naming neither.
local c = lsystem { axiom = "!(0) F !(100) F", angle = 90 }:curve(0)
solid.tube(c, { method = "grid", radius = 1, by = "width", taper = 1e-6 })

-- files: x.vtp
local a = polyline { { 0, 0 }, { 1, 0 } }
save(a, "x.vtp")
save({ a, a }, "x.vtp.pvd")

local a = polyline { { 0, 0 }, { 1, 0 } }
save({ a, a, a, times = { 0, 2, 1 } }, "morph.pvd")

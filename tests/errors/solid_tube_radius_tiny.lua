local t = solid.tube(polyline { {0,0}, {10,0}, {10,10} }, { radius = 1e-8 })

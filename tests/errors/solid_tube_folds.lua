solid.tube(polyline { {0,0}, {10,0}, {10,1}, {0,1} }, { radius = 1 })

solid.tube(polyline { {0,0}, {10,0}, {10,5}, {5,5}, {5,-5} }, { radius = 0.5 })

solid.tube(polyline { {0,0}, {10,0} }, { radius = 1, method = "grid", min_radius = -1 })

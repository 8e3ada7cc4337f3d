solid.relief(polyline { {0,0}, {10,0}, {10,10} }, { height = 2 })

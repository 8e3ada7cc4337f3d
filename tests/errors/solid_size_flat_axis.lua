solid.size(polyline { {0,0}, {1,0} }, { size = 10, axis = "y" })

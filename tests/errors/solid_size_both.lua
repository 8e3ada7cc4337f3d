solid.size(polyline { {0,0}, {1,1} }, { size = 10, fit = {10, 10, 10} })

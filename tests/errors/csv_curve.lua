save(polyline { {0,0}, {1,0} }, "curve.csv")

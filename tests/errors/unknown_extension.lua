local c = polyline { { 0, 0 }, { 1, 0 } }
save(c, "curve.dxf")

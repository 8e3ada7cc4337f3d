local c = polyline { { 0, 0 }, { 1, 0 } }
c:point(1 << 40)

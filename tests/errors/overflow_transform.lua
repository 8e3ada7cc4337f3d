local c = polyline { { 0, 0 }, { 1e10, 0 } }
c:transform { scale = 1e300 }

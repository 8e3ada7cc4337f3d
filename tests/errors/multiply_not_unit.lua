local c = hoist.multiply(polyline { { 0, 0 }, { 2, 0 } }, 3)

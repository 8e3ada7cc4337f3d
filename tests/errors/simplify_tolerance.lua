local s = simplify(polyline { { 0, 0 }, { 1, 0 } }, 0)

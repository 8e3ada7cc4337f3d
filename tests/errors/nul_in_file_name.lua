save(polyline { { 0, 0 }, { 1, 0 } }, "a.svg\0../../escape.svg")

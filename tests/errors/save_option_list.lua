save(polyline { { 0, 0 }, { 1, 1 } }, "x.svg", { colour = "red" })

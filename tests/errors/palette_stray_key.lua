save(polyline { { 0, 0 }, { 1, 0 } }, "c.svg", { stroke = { "red", foo = "blue" } })

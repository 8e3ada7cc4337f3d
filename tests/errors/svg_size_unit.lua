save(polyline { { 0, 0 }, { 1, 0 } }, "c.svg", { size = "15furlongs" })

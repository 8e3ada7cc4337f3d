-- a quote in a colour would break the SVG file
save(polyline { { 0, 0 }, { 1, 0 } }, "c.svg", { stroke = "red\" onload=\"x" })

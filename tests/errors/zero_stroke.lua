-- a stroke width of zero would draw nothing
save(polyline { { 0, 0 }, { 1, 0 } }, "c.svg", { stroke_width = 0 })

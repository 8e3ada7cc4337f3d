-- a finite extent whose stroke width in curve units overflows: no "inf" in the file
save(polyline { { 0, 0 }, { 1.6e308, 0 } }, "b.svg", { stroke_width = 999999, size = 16 })

-- files: twice.svg
-- "./twice.svg" is the same output path as "twice.svg"
save(polyline { { 0, 0 }, { 1, 0 } }, "twice.svg")
save(polyline { { 0, 0 }, { 1, 1 }, { 2, 0 } }, "./twice.svg")

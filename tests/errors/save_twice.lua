-- files: twice.svg
local c = polyline { { 0, 0 }, { 1, 0 } }
save(c, "twice.svg")
save(polyline { { 0, 0 }, { 1, 1 }, { 2, 0 } }, "twice.svg")

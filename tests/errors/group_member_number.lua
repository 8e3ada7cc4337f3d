local a = polyline { { 0, 0 }, { 1, 0 } }
save(group { a, 5 }, "g.svg")

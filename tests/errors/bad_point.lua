local c = polyline { { 0, 0 }, { 1, "a" } }

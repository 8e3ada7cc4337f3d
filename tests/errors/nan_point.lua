local c = polyline { { 0, 0 }, { 0 / 0, 1 } }

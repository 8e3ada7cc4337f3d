local c = substitute { path = polyline { { 0, 0 }, { 1, 0 } }, generator = polyline { { 0, 0 }, { 1, 1 } }, levels = 2 }

local c = substitute { path = polyline { { 0, 0 }, { 1, 0 } }, generator = polyline { { 0, 0 }, { 1, 0 } },
  levels = 2, transforms = { "flip" } }

local P = bspline { points = { { 0, 0 }, { 1, 0 } } }

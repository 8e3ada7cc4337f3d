local P = bspline { points = { { 0, 0 }, { 0.5, 1e308 }, { 1, 0 } } }

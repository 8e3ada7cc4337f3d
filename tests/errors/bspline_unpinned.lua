local P = bspline { points = { { 0, 0 }, { 0.5, 0.5 }, { 2, 0 } } }

local P = bspline { points = { { 2, 2 }, { 3, 3 }, { 2, 2 } }, normalize = true }

local P = bspline { points = { { 0, 0 }, { 0.5, 1 }, { 1e-12, 0 } }, normalize = true }

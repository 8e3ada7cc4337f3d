-- Bowyer's reduction factor against the fractal dimension, as a sweep: one run per factor, each handing back
-- its dimension with result(), which the sweep gathers into results.csv and plots (plot_dimension.svg).
--   selfsim run examples/exclusion_factor_sweep.lua --set factor=0.3..0.9:0.1 -o factor_sweep
local factor = param("factor", 0.5, { min = 0.05, max = 0.95, doc = "radius reduction per level" })
local levels = param("levels", 12, { min = 2, max = 18 })
local square = polygon { {0,0}, {1,0}, {1,1}, {0,1} }
local c = exclusion.curve { region = square, start = polyline { {0,0}, {1,1} }, radius = 0.1, factor = factor,
                            levels = levels }
local fit = dimension(c)
result("dimension", fit.dimension)
result("slope_error", fit.error)
save(c, "curve.svg")

local m = load("load_as_curve_fails.obj")
save(m, "m.svg")

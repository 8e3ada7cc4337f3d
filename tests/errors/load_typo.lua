local m = load("load_bad_fce.obj")

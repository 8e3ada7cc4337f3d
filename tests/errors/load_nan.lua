load("load_nan.stl")

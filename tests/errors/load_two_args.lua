load("a.stl", "b.stl")

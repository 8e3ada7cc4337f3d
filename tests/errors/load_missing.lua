load("no_such_file.stl")

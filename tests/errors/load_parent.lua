load("../golden/whatever.stl")

load("errors.txt")

result(3, 1)

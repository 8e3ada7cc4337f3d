result("2d", 1)

result("", 1)

result("d", 1/0)

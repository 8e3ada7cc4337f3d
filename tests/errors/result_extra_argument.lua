result("d", 1, "units")

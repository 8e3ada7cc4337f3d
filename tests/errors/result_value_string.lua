result("d", "1.26")

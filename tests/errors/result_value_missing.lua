result("d")

result("fit dimension", 1.26)

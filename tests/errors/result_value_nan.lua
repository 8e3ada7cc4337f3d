result("d", 0/0)

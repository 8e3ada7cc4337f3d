result("d", 1)
result("d", 1)
result("d", 2)

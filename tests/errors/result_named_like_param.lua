local x = param("x", 1)
result("x", 2 * x)

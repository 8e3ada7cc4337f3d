result("d", true)

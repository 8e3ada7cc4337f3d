result("count", math.maxinteger)

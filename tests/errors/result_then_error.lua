-- The recipe failed after its result: no results.json is left (the check finds no file).
result("d", 1)
error("stopped")

-- A run gives at most 1000 results: each is a column of a sweep's results.csv and a plot of its own.
for i = 1, 1000 do result("r" .. i, i) end
result("r1", 1) -- the same again is no new result
result("one_more", 1)

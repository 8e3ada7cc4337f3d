-- the iterator pairs() returns may be called by hand, with anything
local next_of = pairs({ a = 1 })
print(next_of(42))

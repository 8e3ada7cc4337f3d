-- What a recipe can and cannot reach: fixed pairs() order, locked metatables, values kept by finalizers
-- that stay recognisably dead, and pcall/coroutines that behave as in plain Lua while no stop is due.

-- pairs(): numbers by value, then strings by bytes, then booleans; the same order in every run.
local t = { pear = 1, apple = 2, [3] = "c", [1] = "a", fig = 3, [true] = 4, [-2.5] = 5, Zebra = 6, [2] = "b" }
local order = {}
for k in pairs(t) do order[#order + 1] = tostring(k) end
assert(table.concat(order, " ") == "-2.5 1 2 3 Zebra apple fig pear true", table.concat(order, " "))

-- Keys removed during the loop are skipped, as with next().
local u = { a = 1, b = 2, c = 3 }
local seen = {}
for k in pairs(u) do
  seen[#seen + 1] = k
  if k == "a" then u.b = nil end
end
assert(table.concat(seen, " ") == "a c", table.concat(seen, " "))

-- __pairs is still honoured.
local custom = setmetatable({}, { __pairs = function() return function(_, k) if not k then return 1, "one" end end, nil, nil end })
for k, v in pairs(custom) do assert(k == 1 and v == "one") end

-- Value metatables are out of reach: no __gc to call from a recipe.
local c = polyline { { 0, 0 }, { 1, 0 } }
assert(getmetatable(c) == "locked")
assert(getmetatable(lsystem { axiom = "F" }) == "locked")
assert(not pcall(setmetatable, c, {}))

-- A curve kept alive by a finalizer is dead, with a clear message, never freed memory.
local zombie
do
  local doomed = polyline { { 0, 0 }, { 2, 0 } }
  setmetatable({}, { __gc = function() zombie = doomed end })
end
collectgarbage()
collectgarbage()
assert(zombie ~= nil)
local ok, message = pcall(function() return zombie:length() end)
assert(not ok and message:find("Curve used after it was freed"), message)
ok, message = pcall(tostring, zombie)
assert(not ok and message:find("used after it was freed"), message)

-- Without a stop, pcall and coroutines behave as in plain Lua, yields through pcall included.
assert(select("#", pcall(function() return 1, 2, 3 end)) == 4)
ok, message = pcall(error, "plain")
assert(not ok and message == "plain")
local co = coroutine.wrap(function(a) local _, b = pcall(coroutine.yield, a + 1); return b * 2 end)
assert(co(1) == 2 and co(5) == 10)
assert(xpcall(function() return true end, print))

-- A finalizer that empties a value while a method is still using it (here from the options table's
-- __index, in the middle of transform) cannot free it under the call: the call holds its own reference.
collectgarbage("incremental", 100, 100, 1) -- small steps, so finalizers run a few at a time
collectgarbage("stop")
local held
do
  local c = polyline { { 0, 0 }, { 3, 4 } }
  for _ = 1, 200 do setmetatable({}, { __gc = function() end }) end
  setmetatable({ c = c }, { __gc = function(o) held = o.c end })
end
repeat collectgarbage("step", 0) until held -- held is back, its own finalizer still queued
local collecting = setmetatable({}, { __index = function() collectgarbage(); collectgarbage() end })
local moved = held:transform(collecting)
assert(moved:point(2)[1] == 3 and moved:point(2)[2] == 4, "the call kept its curve")
ok, message = pcall(function() return held:points() end)
assert(not ok and message:find("used after it was freed"), message)
collectgarbage("restart")
collectgarbage("incremental", 200, 100, 13)

-- math.randomseed() without a seed reseeds from --seed (default 0), never from the clock.
math.randomseed()
local first = math.random()
math.randomseed(0)
assert(math.random() == first)
assert(getmetatable("") == "locked", "the string metatable is shared with scripts/: locked")

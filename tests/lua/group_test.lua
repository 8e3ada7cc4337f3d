-- Several curves in one value: group{}, save({ a, b }), concat(), c:reverse(), and substitute over every
-- path of a group.
local curves = require "selfsim.curves"
local h = require "test_helpers"

local a = curves.dragon():curve(6)                                    -- 65 points, level 6
local b = curves.terdragon():curve(3):transform { translate = { 2, 0 } } -- 28 points, level 3
local sq = polygon { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } }

local g = group { a, { b, stroke = "crimson", stroke_width = 2 }, { sq, fill = "gold" } }
assert(g:points() == 65 + 28 + 5 and g:paths() == 3, tostring(g))
assert(h.near(g:length(), a:length() + b:length() + 4))
local cells = table.concat(g:fields().cells, " ")
assert(cells == "color width fill curve", cells)         -- members' styles, then their numbers
assert(#g:fields().points == 0)  -- the square has no level: a field only some members have is dropped
local ab = group { a, b }
assert(table.concat(ab:fields().points, " ") == "level")  -- levels differ: a per-point field now
assert(ab:level() == nil and group { a, a }:level() == 6)
-- Members keep their points, in order.
assert(g:point(66)[1] == b:point(1)[1] and g:point(66)[2] == b:point(1)[2])

-- Groups of groups, 3D groups are refused when mixed, and a list saves as its group.
local gg = group { g, a }
assert(gg:paths() == 4)
save(g, "g.svg")
save(g, "g.vtp")
save({ a, b }, "ab.svg", { stroke = { "red", "blue" } })
local ok, err = pcall(group, {})
assert(not ok and err:find("a group needs at least one curve", 1, true), err)
ok, err = pcall(group, { a, 5 })
assert(not ok and err:find("member 2 of the group must be a curve", 1, true), err)
ok, err = pcall(group, { { a, colour = "red" } })
assert(not ok and err:find("unknown option 'colour'", 1, true), err)

-- concat: one path; a shared end point is kept once.
local c = concat(polyline { { 0, 0 }, { 1, 0 } }, { { 1, 0 }, { 1, 1 } }, polyline { { 2, 1 }, { 3, 1 } })
assert(c:points() == 5 and c:paths() == 1, tostring(c))
assert(c:point(3)[1] == 1 and c:point(3)[2] == 1)
ok, err = pcall(concat, g)
assert(not ok and err:find("argument 1 has 3 paths", 1, true), err)

-- reverse: the same points walked from the end; twice is the identity.
local r = a:reverse()
assert(r:point(1)[1] == a:point(65)[1] and r:point(65)[2] == a:point(1)[2])
assert(r:reverse():point(7)[1] == a:point(7)[1])
assert(h.near(r:length(), a:length()))

-- substitute works on every path of a group and keeps the members' numbers and styles.
local s = substitute { path = g, generator = { { 0, 0 }, { 0.5, 0.5 }, { 1, 0 } }, levels = 2 }
assert(s:paths() == 3, tostring(s))
assert(s:segments() == 4 * g:segments(), s:segments())
assert(table.concat(s:fields().cells, " ") == "color width fill curve")

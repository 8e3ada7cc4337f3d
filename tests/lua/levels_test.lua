-- v:levels() and v:level(k) (frontend/lua/growth.h): every kernel that grows by levels hands back a value
-- that knows them. Each level is checked against what defines it: a direct call of the kernel at that level
-- (L-system, substitute, hoist.iterate, develop), the final curve's points of level <= k (exclusion.curve),
-- or the kernel's own step (exclusion.surface).
local h = require "test_helpers"
local curves = require "selfsim.curves"

local function names(list) return table.concat(list, " ") end

-- Whether two values are the same: summary, counts, bbox, fields and their ranges, and every point.
local function same(a, b, what)
  assert(tostring(a) == tostring(b), what .. ": " .. tostring(a) .. " vs " .. tostring(b))
  assert(a:points() == b:points(), what)
  local fa, fb = a:fields(), b:fields()
  assert(names(fa.points) == names(fb.points), what .. ": point fields " .. names(fa.points) .. " vs " .. names(fb.points))
  assert(names(fa.cells) == names(fb.cells), what .. ": cell fields " .. names(fa.cells) .. " vs " .. names(fb.cells))
  for _, list in ipairs { fa.points, fa.cells } do
    for _, name in ipairs(list) do
      local alo, ahi = a:range(name)
      local blo, bhi = b:range(name)
      assert(h.near(alo, blo, 1e-12) and h.near(ahi, bhi, 1e-12), what .. ": range of " .. name)
    end
  end
  local ba, bb = a:bbox(), b:bbox()
  for i = 1, #ba.min do
    assert((ba.min[i] == bb.min[i] and ba.max[i] == bb.max[i]) or h.near(ba.min[i], bb.min[i], 1e-12) and h.near(ba.max[i], bb.max[i], 1e-12),
           what .. ": bbox axis " .. i .. ": " .. ba.min[i] .. ".." .. ba.max[i] .. " vs " .. bb.min[i] .. ".." .. bb.max[i])
  end
  for i = 1, a:points() do
    local p, q = a:point(i), b:point(i)
    for j = 1, #p do assert(h.near(p[j], q[j], 1e-12), what .. ": point " .. i .. ": " .. p[j] .. " vs " .. q[j]) end
  end
end

-- levels() has last - first + 1 entries, times first..last, and its last entry is the value itself.
local function check_levels(v, first, last, what)
  local L = v:levels()
  assert(#L == last - first + 1, what .. ": " .. #L .. " levels")
  assert(#L.times == #L, what .. ": times")
  for i, t in ipairs(L.times) do assert(math.type(t) == "integer" and t == first + i - 1, what .. ": time " .. i) end
  assert(rawequal(L[#L], v), what .. ": the last level is not the value itself")
  assert(rawequal(v:level(last), v), what .. ": level(last) is not the value itself")
  for i = 1, #L - 1 do same(L[i], v:level(first + i - 1), what .. " levels()[" .. i .. "] vs level()") end
  return L
end

-- An error raised by f(...), checked against a Lua pattern.
local function fails(pattern, f, ...)
  local ok, err = pcall(f, ...)
  assert(not ok, "expected an error matching " .. pattern)
  assert(tostring(err):find(pattern), tostring(err))
end

---------------------------------------------------------------------------------------------------------
-- L-system: g:curve{ level = n } has levels 0..n, each g:curve{ level = k } with the same options.
for _, case in ipairs {
  { g = curves.dragon(), n = 6, opts = {} },
  { g = curves.dragon(), n = 5, opts = { normalize = false } },
  { g = curves.koch_snowflake(), n = 3, opts = {} },  -- closed
  { g = lsystem { axiom = "X", rules = { X = "F+[[X]-X]-F[-FX]+X", F = "FF" }, angle = 25, start_angle = 70 },
    n = 3, opts = { normalize = false } },            -- branched: several paths, branch_order and root_distance
} do
  local function at(k)
    local o = { level = k }
    for key, value in pairs(case.opts) do o[key] = value end
    return case.g:curve(o)
  end
  local c = at(case.n)
  local L = check_levels(c, 0, case.n, "L-system " .. tostring(c))
  assert(c:level() == case.n, "c:level() without argument")
  for k = 0, case.n do
    same(c:level(k), at(k), "L-system level " .. k)
    assert(c:level(k):level() == k)
    -- a level's own levels stop at it
    assert(#c:level(k):levels() == k + 1 and c:level(k):levels().times[k + 1] == k)
  end
  assert(L[1]:points() < L[#L]:points())
end
-- g:curve(n), the short form, has the same levels.
same(curves.dragon():curve(4):level(2), curves.dragon():curve { level = 2 }, "g:curve(n)")
-- level 0 has one level.
local zero = curves.dragon():curve { level = 0 }
assert(#zero:levels() == 1 and zero:levels().times[1] == 0 and rawequal(zero:level(0), zero))

---------------------------------------------------------------------------------------------------------
-- substitute{ levels = n }: levels 0..n, each the substitution done k times with the same options.
local tent = polyline { { 0, 0 }, { 0.5, 0.5 }, { 1, 0 } }
for _, case in ipairs {
  { path = { { 0, 0 }, { 1, 0 } }, generator = tent, transforms = { "identity", "half_turn" }, n = 5 },
  { path = polygon { { 0, 0 }, { 1, 0 }, { 0.5, 0.8 } }, generator = { { 0, 0 }, { 1 / 3, 0 }, { 0.5, 0.3 }, { 2 / 3, 0 }, { 1, 0 } },
    n = 3 },
  { path = group { polyline { { 0, 0 }, { 1, 0 } }, polyline { { 0, 1 }, { 1, 1 } } }, generator = tent, n = 3 },
} do
  local function at(k)
    return substitute { path = case.path, generator = case.generator, transforms = case.transforms, levels = k }
  end
  local s = at(case.n)
  check_levels(s, 0, case.n, "substitute")
  for k = 0, case.n do same(s:level(k), at(k), "substitute level " .. k) end
end

---------------------------------------------------------------------------------------------------------
-- hoist.iterate: generations 0..n, each hoist.iterate with generations = k and the same options.
local B = bspline { points = { { 0, 0 }, { 0.25, 0.4 }, { 0.6, -0.3 }, { 1, 0 } } }
for _, opts in ipairs {
  { multiplicity = 3, boundary = "rotate", segments = "reflect_y" },
  { multiplicity = 2 },
} do
  local function at(k)
    local o = { generations = k }
    for key, value in pairs(opts) do o[key] = value end
    return hoist.iterate(B, o)
  end
  local it = at(3)
  check_levels(it, 0, 3, "hoist.iterate")
  for k = 0, 3 do same(it:level(k), at(k), "hoist.iterate generation " .. k) end
  -- (n - 1)·m^g + 1 points
  for k = 0, 3 do assert(it:level(k):points() == (B:points() - 1) * opts.multiplicity ^ k + 1, k) end
end

---------------------------------------------------------------------------------------------------------
-- develop: levels 1..n, level k the surface of the stack's first k + 1 curves = develop{ levels = k }.
for _, opts in ipairs {
  { check = false },
  { smooth = 1, corner_shift = 0.1 },
  { smooth = 2, corner_shift = 0.1, stencil = "bounded" },
} do
  local function at(k)
    local o = { levels = k }
    for key, value in pairs(opts) do o[key] = value end
    return develop(curves.dragon(), o)
  end
  local d = at(4)
  check_levels(d, 1, 4, "develop")
  for k = 1, 4 do same(d:level(k), at(k), "develop level " .. k) end
end
-- A stack given as curves: levels 1..#stack - 1.
local stack = {}
for l = 0, 4 do stack[#stack + 1] = curves.dragon():curve { level = l } end
local ds = develop(stack, { check = false })
check_levels(ds, 1, 4, "develop of a list")
for k = 1, 4 do
  local first = {}
  for l = 1, k + 1 do first[l] = stack[l] end
  same(ds:level(k), develop(first, { check = false }), "develop of a list, level " .. k)
end
fails("level must be an integer in %[1, 4%], got 0", ds.level, ds, 0)

-- develop with size: every step is scaled as the whole was (the factor that made the whole `size`), so
-- step k is the unscaled develop{ levels = k } times that one factor, and level 0's segment (points 1, 2)
-- is as long in every step.
local sized = develop(curves.dragon(), { levels = 4, size = 10, check = false })
local sb = sized:bbox()
assert(h.near(math.max(sb.max[1] - sb.min[1], sb.max[2] - sb.min[2], sb.max[3] - sb.min[3]), 10, 1e-9))
local factor = sized:point(2)[1]  -- the unit segment (0,0,0)-(1,0,0), scaled
assert(factor > 1 and h.near(sized:point(1)[1], 0))
for k = 1, 4 do
  local step, plain = sized:level(k), develop(curves.dragon(), { levels = k, check = false })
  assert(step:points() == plain:points() and step:faces() == plain:faces(), k)
  assert(h.near(step:point(2)[1], factor, 1e-9), "step " .. k .. ": level 0 is " .. step:point(2)[1] .. " long")
  local a, b = step:bbox(), plain:bbox()
  for i = 1, 3 do
    assert(h.near(a.min[i], factor * b.min[i], 1e-9) and h.near(a.max[i], factor * b.max[i], 1e-9),
           "step " .. k .. " bbox axis " .. i)
    -- contained in the whole (an unsmoothed stack's first levels are part of it)
    assert(a.min[i] >= sb.min[i] - 1e-9 and a.max[i] <= sb.max[i] + 1e-9, "step " .. k .. " outside the whole")
  end
  for i = 1, step:points(), 7 do
    local p, q = step:point(i), plain:point(i)
    for j = 1, 3 do assert(h.near(p[j], factor * q[j], 1e-9), "step " .. k .. " point " .. i) end
  end
end
-- Smoothed, sized: the level-0 corners stay put, so level 0's segment is as long in every step.
local smooth_sized = develop(curves.dragon(), { levels = 4, size = 10, smooth = 1, corner_shift = 0.1 })
for k = 1, 4 do
  local step = smooth_sized:level(k)
  assert(h.near(step:point(2)[1], smooth_sized:point(2)[1], 1e-9), k)
  local a, b = step:bbox(), smooth_sized:bbox()
  -- every step's depth is within the whole's: the whole is the deepest
  assert(a.min[3] >= b.min[3] - 1e-9 and a.max[3] <= b.max[3] + 1e-9, k)
end
-- size_level: level 0 becomes 80 long, in every step (also those before size_level).
for _, size_level in ipairs { 0, 3 } do
  local by_level = develop(curves.dragon(), { levels = 4, size = 80, size_level = size_level, check = false })
  local len = by_level:point(2)[1]
  if size_level == 0 then assert(h.near(len, 80, 1e-9)) end
  for k = 1, 4 do
    assert(h.near(by_level:level(k):point(2)[1], len, 1e-9),
           "size_level " .. size_level .. ", step " .. k .. ": " .. by_level:level(k):point(2)[1] .. " vs " .. len)
  end
end

---------------------------------------------------------------------------------------------------------
-- exclusion.curve: level k is exactly the final curve's points of level <= k, in their order (placed
-- points never move), with the same paths; as many as the start's points plus the splits of levels 1..k.
local function key(p) return string.format("%.17g %.17g", p[1], p[2]) end
local square = polygon { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } }
local hole = {}
for k = 0, 23 do hole[#hole + 1] = { 0.5 + 0.2 * math.cos(2 * math.pi * k / 24), 0.5 + 0.2 * math.sin(2 * math.pi * k / 24) } end
for _, case in ipairs {
  { region = square, start = polyline { { 0, 0 }, { 1, 1 } }, radius = 0.1 },
  { region = square, start = polygon { { 0.25, 0.25 }, { 0.75, 0.25 }, { 0.75, 0.75 }, { 0.25, 0.75 } }, radius = 0.1 },
  { region = square, start = group { polyline { { 0.1, 0.3 }, { 0.9, 0.3 } }, polyline { { 0.1, 0.7 }, { 0.5, 0.55 }, { 0.9, 0.7 } } },
    radius = 0.1 },
  { region = group { square, polygon(hole) }, start = polygon { { 0.15, 0.15 }, { 0.85, 0.15 }, { 0.85, 0.85 }, { 0.15, 0.85 } },
    radius = 0.05 },
} do
  local n = 6
  local function at(k)
    return exclusion.curve { region = case.region, start = case.start, radius = case.radius, factor = 0.8, levels = k }
  end
  local c, report = at(n)
  check_levels(c, 0, n, "exclusion.curve")
  local lo, hi = c:range("level")
  assert(lo == 0 and hi == n, hi)
  local start_points = case.start:points()
  local expected = start_points
  local previous = nil
  for k = 0, n do
    if k > 0 then expected = expected + report.levels[k].splits end
    local ck = c:level(k)
    assert(ck:points() == expected, "exclusion.curve level " .. k .. ": " .. ck:points() .. " points, expected " .. expected)
    assert(ck:paths() == c:paths() and ck:paths() == case.start:paths())
    assert(names(ck:fields().points) == names(c:fields().points) and names(ck:fields().cells) == names(c:fields().cells))
    local klo, khi = ck:range("level")
    assert(klo == 0 and khi == k, "exclusion.curve level " .. k .. " has levels up to " .. khi)
    -- a subsequence of the final curve's points (the same points, in the same order)
    local j = 1
    for i = 1, ck:points() do
      local want = key(ck:point(i))
      while j <= c:points() and key(c:point(j)) ~= want do j = j + 1 end
      assert(j <= c:points(), "exclusion.curve level " .. k .. ": point " .. i .. " is not the final curve's")
      j = j + 1
    end
    -- and of the next level's
    if previous then assert(previous:points() < ck:points() or report.levels[k].splits == 0) end
    previous = ck
    -- the kernel run to level k makes the same curve
    same(ck, at(k), "exclusion.curve level " .. k)
  end
  assert(expected == c:points())
end

---------------------------------------------------------------------------------------------------------
-- exclusion.surface: level k is the mesh after level k: start·4^k faces, levels 0..k.
local ball = volume.sphere { center = { 0, 0, 0 }, radius = 1 }
for _, start in ipairs {
  { { -.6, -.4, 0 }, { .6, -.4, 0 }, { 0, .6, 0 } },
  mesh { points = { { -.5, -.5, 0 }, { .5, -.5, 0 }, { .5, .5, 0 }, { -.5, .5, 0 } }, triangles = { { 1, 2, 3 }, { 1, 3, 4 } } },
} do
  local n = 3
  local f, report = exclusion.surface { region = ball, start = start, radius = 0.2, factor = 0.8, levels = n }
  local L = check_levels(f, 0, n, "exclusion.surface")
  local start_faces = L[1]:faces()
  assert(start_faces == (start.faces and start:faces() or 1), start_faces)
  for k = 0, n do
    local m = f:level(k)
    assert(m:faces() == start_faces * 4 ^ k, "exclusion.surface level " .. k .. ": " .. m:faces() .. " faces")
    if k > 0 then assert(m:faces() == report.levels[k].triangles) end
    local lo, hi = m:range("level")
    assert(lo == 0 and hi == k, "exclusion.surface level " .. k .. ": levels " .. lo .. ".." .. hi)
    assert(names(m:fields().points) == names(f:fields().points) and names(m:fields().cells) == names(f:fields().cells))
    local b, fb = m:bbox(), f:bbox()
    for i = 1, 3 do assert(b.min[i] >= -1 - 0.1 and b.max[i] <= 1 + 0.1, "outside the ball") end
  end
  same(f:level(n), f, "exclusion.surface last level")
end

---------------------------------------------------------------------------------------------------------
-- Errors.
local c = curves.dragon():curve { level = 3 }
fails("level: level must be an integer in %[0, 3%], got 4", c.level, c, 4)
fails("level: level must be an integer in %[0, 3%], got %-1", c.level, c, -1)
fails("level: level must be an integer in %[0, 3%], got 1%.5", c.level, c, 1.5)
fails("levels: takes no arguments", c.levels, c, 1)
fails("level: takes one level number", c.level, c, 1, 2)
local it = hoist.iterate(B, { multiplicity = 2, generations = 2 })
fails("level: generation must be an integer in %[0, 2%], got 3", it.level, it, 3)
local plain = polyline { { 0, 0 }, { 1, 0 } }
assert(plain:level() == nil)
fails("levels: this value has no levels", plain.levels, plain)
fails("level: this value has no levels", plain.level, plain, 0)
-- A transformed value has none either; its source keeps its own.
local moved = c:transform { scale = 2 }
fails("levels: this value has no levels", moved.levels, moved)
assert(#c:levels() == 4)
local m = mesh { points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, triangles = { { 1, 2, 3 } } }
fails("levels: this value has no levels", m.levels, m)
fails("level: this value has no levels", m.level, m, 0)

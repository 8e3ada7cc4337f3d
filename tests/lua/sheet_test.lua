-- selfsim.sheet: each entry scaled to fit a unit cell and centred in it, cells row by row from the top left.
local sheet = require "selfsim.sheet"
local h = require "test_helpers"

local line = polyline { { 0, 0 }, { 2, 0 } }                 -- 2 wide, flat: scaled by 1/2, centred vertically
local square = polygon { { 5, 5 }, { 8, 5 }, { 8, 8 }, { 5, 8 } } -- 3 wide: scaled by 1/3, moved to cell 2
local s = sheet.grid({ line, { square, stroke = "red" }, line }, { columns = 2, gap = 0.5 })
assert(s:paths() == 3 and s:points() == 2 + 5 + 2, tostring(s))
local function at(i, x, y) assert(h.near(s:point(i)[1], x) and h.near(s:point(i)[2], y), i) end
at(1, 0, 0.5)
at(2, 1, 0.5)
at(3, 1.5, 0) -- column 2 starts at 1 + gap
at(5, 2.5, 1)
at(8, 0, -1.5 + 0.5) -- row 2 is 1 + gap lower
assert(table.concat(s:fields().cells, " ") == "color curve") -- only the style given

-- Default columns: a square-ish grid (5 entries: 3 columns, 2 rows).
local five = sheet.grid { line, line, line, line, line }
local box = five:bbox()
assert(h.near(box.max[1], 3 + 2 * 0.15) and h.near(box.min[2], -1.15 + 0.5), box.max[1] .. " " .. box.min[2])

for _, bad in ipairs {
  { { line }, { colums = 2 }, "unknown option 'colums'" },
  { { line }, { columns = 0 }, "option 'columns' must be a whole number from 1" },
  { { line }, { gap = -1 }, "option 'gap' must be a number in [0, 10]" },
  { {}, nil, "expected at least one curve" },
  { { 5 }, nil, "entry 1 must be a 2D curve" },
} do
  local ok, err = pcall(sheet.grid, bad[1], bad[2])
  assert(not ok and err:find(bad[3], 1, true), err)
end

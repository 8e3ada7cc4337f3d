-- The value model from a recipe: meshes from tables, the methods every value has, save() by format and
-- load() back from the recipe's folder (the output folder is its own folder here: tests/CMakeLists.txt runs
-- this script with -o, and load() reads beside the recipe, so only mesh{} values are compared), whole-number
-- levels, and the level a curve records.
local m = mesh { points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } },
                 triangles = { { 1, 3, 2 }, { 1, 2, 4 }, { 2, 3, 4 }, { 3, 1, 4 } } }
assert(m:points() == 4 and m:faces() == 4)
assert(tostring(m) == "Mesh(4 points, 4 faces)", tostring(m))
local b = m:bbox()
assert(b.min[1] == 0 and b.min[2] == 0 and b.min[3] == 0 and b.max[1] == 1 and b.max[2] == 1 and b.max[3] == 1)
assert(#m:fields().points == 0 and #m:fields().cells == 0)
for _, ext in ipairs { "vtp", "vtu", "stl", "obj", "ply", "VTP" } do save(m, "tet." .. ext) end

-- A whole float is the integer it is; the curve records its level as a field.
local g = (require "selfsim.curves").dragon()
local c = g:curve(8.0)
assert(c:segments() == 256 and c:level() == 8, tostring(c))
assert(g:curve { level = 12 / 2 }:segments() == 64)
assert(g:string(2.0) == "FX-YF-FX+YF")
assert(c:fields().points[1] == "level")
assert(polyline { { 0, 0 }, { 1, 0 } }:level() == nil)

-- A 3D point has three coordinates; bounding boxes of curves have two.
local cb = c:bbox()
assert(#cb.min == 2 and #b.min == 3)

-- Curves save as .vtu too; meshes are refused by .svg with the list of formats that hold them.
save(c, "dragon.vtu")
local ok, err = pcall(save, m, "tet.svg")
assert(not ok and err:find("expected one of: '.3mf', '.obj', '.ply', '.stl', '.vdb', '.vtp', '.vtu'", 1, true), err)

-- load() reads beside the recipe: a quad becomes two triangles; a flat .vtp polyline is a 2D curve.
local sq = load("square.obj")
assert(sq:points() == 4 and sq:faces() == 2, tostring(sq))
local corner = load("corner.vtp")
assert(tostring(corner) == "Curve(3 points, 1 paths)", tostring(corner))
assert(corner:length() == 2)
assert(table.concat(corner:fields().points, " ") == "arclength")  -- written by save(), read back as a field
assert(table.concat(corner:fields().cells, " ") == "path")

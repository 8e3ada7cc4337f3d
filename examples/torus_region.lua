-- A torus as a closed triangle mesh, saved as torus.stl: the region examples/exclusion_torus.lua grows a
-- surface in (torus.stl beside it is this recipe's output). Major radius 1, tube radius 0.4, around z.
--   selfsim run examples/torus_region.lua
local around, across = param("around", 96), param("across", 32)
local points, triangles = {}, {}
for i = 0, around - 1 do
  local u = 2 * math.pi * i / around
  for j = 0, across - 1 do
    local v = 2 * math.pi * j / across
    local r = 1 + 0.4 * math.cos(v)
    points[#points + 1] = { r * math.cos(u), r * math.sin(u), 0.4 * math.sin(v) }
  end
end
local function index(i, j) return (i % around) * across + (j % across) + 1 end
for i = 0, around - 1 do
  for j = 0, across - 1 do
    local a, b, c, d = index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)
    triangles[#triangles + 1] = { a, b, c }
    triangles[#triangles + 1] = { a, c, d }
  end
end
local torus = mesh { points = points, triangles = triangles }
save(torus, "torus.stl")

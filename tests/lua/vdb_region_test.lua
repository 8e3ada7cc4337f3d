-- A region read from a .vdb level set (ball.vdb: selfsim's own save of the unit sphere at voxel 0.2):
-- its surface as a closed region within a voxel of the sphere, a region exclusion surfaces grow in, a part
-- of unions, and load() gives the same surface as a mesh.
local ball = volume.vdb("ball.vdb")
local box = ball:bbox()
for axis = 1, 3 do
  assert(math.abs(box.min[axis] + 1) < 0.2 and math.abs(box.max[axis] - 1) < 0.2, "bbox axis " .. axis)
end
assert(tostring(ball):find("mesh of"), tostring(ball))

-- Every point of the surface lies within a voxel of the unit sphere.
local m = load("ball.vdb")
for i = 1, m:points() do
  local p = m:point(i)
  local r = math.sqrt(p[1] ^ 2 + p[2] ^ 2 + p[3] ^ 2)
  assert(math.abs(r - 1) < 0.2, "point " .. i .. " at radius " .. r)
end

-- A region to grow in: four splits of one triangle, every one inside.
local f = exclusion.surface { region = ball, start = { { -.5, -.4, 0 }, { .5, -.4, 0 }, { 0, .5, 0 } },
                              radius = 0.15, factor = 0.8, levels = 3 }
assert(f:faces() == 64, tostring(f))
for i = 1, f:points() do
  local p = f:point(i)
  assert(p[1] ^ 2 + p[2] ^ 2 + p[3] ^ 2 < 1, "point " .. i .. " outside the ball")
end

-- A part of a union and a difference.
local u = volume.union { ball, volume.box { min = { 0.5, -0.2, -0.2 }, max = { 1.6, 0.2, 0.2 } } }
assert(u:bbox().max[1] > 1.5)
local d = volume.difference { volume.box { min = { -2, -2, -2 }, max = { 2, 2, 2 } }, ball }
assert(d:bbox().min[1] < -1.9)

-- Errors: a grid that is not there, an option for .vdb files on a mesh, a name that is not a .vdb.
local ok, message = pcall(volume.vdb, "ball.vdb", { grid = "density" })
assert(not ok and message:find("no grid named 'density' %(its grids: 'surface'%)"), message)
ok, message = pcall(volume.vdb, "square.obj")
assert(not ok and message:find("not a .vdb file"), message)

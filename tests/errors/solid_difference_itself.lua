-- A solid less itself: nothing is left, which no voxel changes (it said to give a smaller 'voxel').
local function cube(x, s)
  return mesh { points = { { x, 0, 0 }, { x + s, 0, 0 }, { x + s, s, 0 }, { x, s, 0 },
                           { x, 0, s }, { x + s, 0, s }, { x + s, s, s }, { x, s, s } },
                triangles = { { 1, 3, 2 }, { 1, 4, 3 }, { 5, 6, 7 }, { 5, 7, 8 }, { 1, 2, 6 }, { 1, 6, 5 },
                              { 2, 3, 7 }, { 2, 7, 6 }, { 3, 4, 8 }, { 3, 8, 7 }, { 4, 1, 5 }, { 4, 5, 8 } } }
end
local c = cube(0, 10)
solid.difference(c, c)

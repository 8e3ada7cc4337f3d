-- args: --max-points 300
-- solid.union predicts what it holds before it copies anything: each solid turned outwards, a pair's joined
-- copy or the result, and the intersection search (305 points for two boxes; 80 was predicted before)
local function box(x0, y0, z0, x1, y1, z1)
  return mesh { points = { { x0, y0, z0 }, { x1, y0, z0 }, { x1, y1, z0 }, { x0, y1, z0 },
                           { x0, y0, z1 }, { x1, y0, z1 }, { x1, y1, z1 }, { x0, y1, z1 } },
                triangles = { { 1, 3, 2 }, { 1, 4, 3 }, { 5, 6, 7 }, { 5, 7, 8 }, { 1, 2, 6 }, { 1, 6, 5 },
                              { 2, 3, 7 }, { 2, 7, 6 }, { 3, 4, 8 }, { 3, 8, 7 }, { 4, 1, 5 }, { 4, 5, 8 } } }
end
solid.union { box(0, 0, 0, 10, 10, 10), box(20, 0, 0, 30, 10, 10) }

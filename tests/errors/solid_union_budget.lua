-- args: --max-points 100
-- solid.union predicts what it holds before it copies anything: each solid turned outwards, a pair's joined
-- copy or the result, and the intersection search (107 points for two tetrahedra; 32 was predicted before)
local function tetrahedron(x)
  return mesh { points = { { x, 0, 0 }, { x + 1, 0, 0 }, { x, 1, 0 }, { x, 0, 1 } },
                triangles = { { 1, 3, 2 }, { 1, 2, 4 }, { 1, 4, 3 }, { 2, 3, 4 } } }
end
solid.union { tetrahedron(0), tetrahedron(5) }

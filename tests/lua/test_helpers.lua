-- Shared by the Lua tests, and proof that `require` finds modules in the recipe's own folder.
local M = {}

function M.near(a, b, tol) return math.abs(a - b) <= (tol or 1e-9) end

-- A closed box from (x0, y0, z0) to (x1, y1, z1), facing outwards: a solid for the print tests.
function M.box(x0, y0, z0, x1, y1, z1)
  return mesh { points = { { x0, y0, z0 }, { x1, y0, z0 }, { x1, y1, z0 }, { x0, y1, z0 },
                           { x0, y0, z1 }, { x1, y0, z1 }, { x1, y1, z1 }, { x0, y1, z1 } },
                triangles = { { 1, 3, 2 }, { 1, 4, 3 }, { 5, 6, 7 }, { 5, 7, 8 }, { 1, 2, 6 }, { 1, 6, 5 },
                              { 2, 3, 7 }, { 2, 7, 6 }, { 3, 4, 8 }, { 3, 8, 7 }, { 4, 1, 5 }, { 4, 5, 8 } } }
end

return M

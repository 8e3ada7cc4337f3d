-- Shared by the Lua tests, and proof that `require` finds modules in the recipe's own folder.
local M = {}

function M.near(a, b, tol) return math.abs(a - b) <= (tol or 1e-9) end

return M

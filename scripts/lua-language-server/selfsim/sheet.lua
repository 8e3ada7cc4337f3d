---@meta selfsim.sheet
-- require "selfsim.sheet" (scripts/selfsim/sheet.lua) for lua-language-server: contact sheets. See
-- ../selfsim.lua for how this folder is laid out and checked.

---Contact sheets: several curves laid out in a grid as one group.
---@class selfsim.sheet
local sheet = {}

---@class selfsim.GridOptions
---@field columns? integer columns of the grid (default a square-ish grid)
---@field gap? number space between cells, as a fraction of a cell, 0 to 10 (0.15)

---A group laying the entries out in a grid of square cells, row by row from the top left, each curve
---scaled to fit its cell and centred in it.
---@param entries (selfsim.Curve|selfsim.StyledMember)[] 2D curves, or { curve, stroke = ... }
---@param options? selfsim.GridOptions
---@return selfsim.Curve
function sheet.grid(entries, options) end

return sheet

-- Contact sheets: several curves laid out in a grid as one group{}, each scaled to fit its square cell and
-- centred in it, so a sweep of variants is one value and one SVG (seed 000's Figures 7-10 are such sweeps).
--
--   local sheet = require "selfsim.sheet"
--   save(sheet.grid({ a, b, { c, stroke = "crimson" } }, { columns = 2 }), "sheet.svg")
--
-- Entries are curves, or { curve, stroke = ..., stroke_width = ..., fill = ... } as group{} takes them.
-- Options: columns (default: a square-ish grid), gap (space between cells, as a fraction of a cell; 0.15).
local M = {}

local function check_options(options)
  if options == nil then return {} end
  if type(options) ~= "table" then error("sheet.grid: options must be a table, got " .. type(options), 3) end
  for key in pairs(options) do
    if key ~= "columns" and key ~= "gap" then
      error("sheet.grid: unknown option '" .. tostring(key) .. "' (expected columns, gap)", 3)
    end
  end
  return options
end

-- The curve of an entry, and a function rebuilding the entry around a moved curve (its style kept).
local function split(entry, i)
  if type(entry) == "table" and getmetatable(entry) == nil then
    local style = {}
    for key, value in pairs(entry) do
      if key ~= 1 then style[key] = value end
    end
    return entry[1], function(curve)
      local member = { curve }
      for key, value in pairs(style) do member[key] = value end
      return member
    end
  end
  if entry == nil then error("sheet.grid: entry " .. i .. " is nil", 3) end
  return entry, function(curve) return curve end
end

function M.grid(entries, options)
  if type(entries) ~= "table" then error("sheet.grid: expected a list of curves, got " .. type(entries), 2) end
  options = check_options(options)
  local n = #entries
  if n == 0 then error("sheet.grid: expected at least one curve", 2) end
  local columns = options.columns or math.ceil(math.sqrt(n))
  local gap = options.gap or 0.15
  if math.type(columns) == nil or columns ~= math.floor(columns) or columns < 1 then
    error("sheet.grid: option 'columns' must be a whole number from 1, got " .. tostring(columns), 2)
  end
  if type(gap) ~= "number" or not (gap >= 0 and gap <= 10) then
    error("sheet.grid: option 'gap' must be a number in [0, 10], got " .. tostring(gap), 2)
  end
  local pitch = 1 + gap
  local members = {}
  for i = 1, n do
    local curve, rebuild = split(entries[i], i)
    local ok, box = pcall(function() return curve:bbox() end)
    if not ok or #box.min ~= 2 then
      error("sheet.grid: entry " .. i .. " must be a 2D curve, or { curve, stroke = ... }", 2)
    end
    local w, h = box.max[1] - box.min[1], box.max[2] - box.min[2]
    local size = math.max(w, h)
    local scale = size > 0 and 1 / size or 1
    local row, column = (i - 1) // columns, (i - 1) % columns
    -- Scale about the origin, then move the box's centre to the cell's centre; rows go downwards.
    local cx, cy = (box.min[1] + box.max[1]) / 2 * scale, (box.min[2] + box.max[2]) / 2 * scale
    members[i] = rebuild(curve:transform {
      scale = scale, translate = { column * pitch + 0.5 - cx, -row * pitch + 0.5 - cy },
    })
  end
  return group(members)
end

return M

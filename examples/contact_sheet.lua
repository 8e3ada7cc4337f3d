-- A contact sheet of variants (seed 000 §1, Figure 2): the two-segment tent generator with each of Kaplan's
-- four transforms on each segment, substituted `levels` times: 16 curves, one SVG. Row i has transform i on
-- the first segment, column j transform j on the second; the Lévy C curve is (identity, identity), the
-- Heighway dragon (identity, half_turn). Each row gets its own colour.
--   selfsim run examples/contact_sheet.lua --set levels=12
local sheet = require "selfsim.sheet"
local levels = param("levels", 10)

local transforms = { "identity", "reflect_segment", "reflect_bisector", "half_turn" }
local colours = { "#1d3557", "#e63946", "#2a9d8f", "#e9a23b" }
local tent = polyline { { 0, 0 }, { 0.5, 0.5 }, { 1, 0 } }

local variants = {}
for i, first in ipairs(transforms) do
  for _, second in ipairs(transforms) do
    local c = substitute { path = { { 0, 0 }, { 1, 0 } }, generator = tent, levels = levels,
                           transforms = { first, second } }
    variants[#variants + 1] = { c, stroke = colours[i] }
  end
end

local s = sheet.grid(variants, { columns = 4 })
save(s, "contact_sheet.svg", { stroke_width = 0.8 })
save(s, "contact_sheet.vtp") -- cell fields: curve (which variant), color (its row's colour)

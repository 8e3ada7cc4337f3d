-- Seed 002 §1, Figures 2 and 4: six steps of the terdragon and of the dragon with their corners rounded by
-- circular arcs whose radius follows the segment length (c:rounded), so successive steps stay locally alike:
-- where segments are equally long the arcs meet at the segment midpoints and the path is a union of arcs.
-- These are the slices route 2 of develop (method = "bezier") smooths its levels into.
--   selfsim run examples/develop_rounded.lua --set samples=16
local curves = require "selfsim.curves"
local sheet = require "selfsim.sheet"
local samples = param("samples", 8)

local function steps(grammar, first, colour)
  local row = {}
  for level = first, first + 5 do
    row[#row + 1] = { grammar:curve { level = level }:rounded { samples = samples }, stroke = colour }
  end
  return row
end

save(sheet.grid(steps(curves.terdragon(), 1, "#1d3557"), { columns = 3 }), "terdragon_rounded.svg",
     { stroke_width = 1.2 })                                            -- Figure 2
save(sheet.grid(steps(curves.dragon(), 2, "#e63946"), { columns = 3 }), "dragon_rounded.svg",
     { stroke_width = 1.2 })                                            -- Figure 4

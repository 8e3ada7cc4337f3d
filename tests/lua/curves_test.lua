-- The shipped curves (scripts/selfsim/curves.lua) against their closed forms, through the DSL itself.
local curves = require "selfsim.curves"

local near = require("test_helpers").near

local counts = {
  dragon = function(n) return 2 ^ n end,
  terdragon = function(n) return 3 ^ n end,
  arrowhead = function(n) return 3 ^ n end,
  koch = function(n) return 4 ^ n end,
  koch_snowflake = function(n) return 3 * 4 ^ n end,
  gosper = function(n) return 7 ^ n end,
  hilbert = function(n) return 4 ^ (n + 1) - 1 end,
}
for name, formula in pairs(counts) do
  local g = curves[name]()
  for n = 0, 6 do
    local c = g:curve { level = n }
    assert(c:segments() == formula(n), name .. " level " .. n .. ": " .. c:segments() .. " segments")
    assert(g:count(n) == formula(n), name .. " level " .. n .. ": predicted " .. g:count(n))
    if name ~= "koch_snowflake" then
      local last = c:point(c:points())
      assert(near(last[1], 1) and near(last[2], 0), name .. " level " .. n .. " does not end at (1,0)")
    end
  end
end

-- Koch snowflake: perimeter 3 (4/3)^n.
for n = 0, 6 do
  assert(near(curves.koch_snowflake():curve { level = n }:length(), 3 * (4 / 3) ^ n))
end

-- Arrowhead star and hexagon: six arrowhead curves on unit chords, closed.
for _, ring in ipairs { curves.arrowhead_star(3), curves.arrowhead_hexagon(3) } do
  assert(ring:segments() == 6 * 27)
  local first, last = ring:point(1), ring:point(ring:points())
  assert(near(first[1], last[1]) and near(first[2], last[2]), "ring not closed")
  assert(near(ring:length(), 6 * 1.5 ^ 3), "ring length " .. ring:length())
end
-- The star's triangles point outwards: it reaches further from the centre than the hexagon.
local sb, hb = curves.arrowhead_star(3):bbox(), curves.arrowhead_hexagon(3):bbox()
assert(sb.max[2] - sb.min[2] > hb.max[2] - hb.min[2] + 0.5)

-- Un-normalised arrowhead levels run along the x axis too, thanks to the start angle list.
for n = 0, 5 do
  local c = curves.arrowhead():curve { level = n, normalize = false }
  local last = c:point(c:points())
  assert(near(last[1], 1) and near(last[2], 0), "unnormalised arrowhead level " .. n)
end

-- param() returns its default without --set.
assert(param("some_level", 3) == 3 and math.type(param("some_level", 3)) == "integer")

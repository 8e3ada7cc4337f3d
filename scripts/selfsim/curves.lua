-- The classic curves as grammars (seed 002, Table 1; seed 001), and the arrowhead compositions of seed 001.
-- Every grammar's shrink is the ratio of step lengths between consecutive levels, so that un-normalised
-- curves (normalize = false) and closed curves keep their size from level to level.
local M = {}

-- The grammar constructors take no arguments: a level passed to one (curves.dragon(12)) would otherwise be
-- ignored without a word. Errors name the caller's line.
local function grammar(name, make)
  M[name] = function(...)
    if select("#", ...) > 0 then
      error(name .. "() takes no arguments: it returns the grammar; draw a level with curves." .. name ..
        "():curve(n)", 2)
    end
    return make()
  end
end

-- The level argument of the curve functions: a whole number from 0.
local function level_argument(name, n)
  if math.type(n) == nil or n ~= math.floor(n) or n < 0 then
    error(name .. "(n) expects a level, a whole number from 0, got " .. tostring(n), 3)
  end
  return n
end

-- Heighway dragon: one segment becomes two, scaled by 1/sqrt(2). 2^n segments.
grammar("dragon", function()
  return lsystem { axiom = "FX", rules = { X = "X-YF", Y = "FX+Y" }, angle = 90, shrink = math.sqrt(0.5) }
end)

-- Davis-Knuth terdragon: one segment becomes three, scaled by 1/sqrt(3). 3^n segments.
grammar("terdragon", function()
  return lsystem { axiom = "F", rules = { F = "F-F+F" }, angle = 120, shrink = 1 / math.sqrt(3) }
end)

-- Hilbert curve with Table 1's axiom (level 0 already visits the 2x2 grid): level n visits every cell of
-- the 2^(n+1) x 2^(n+1) grid once, in 4^(n+1) - 1 segments.
grammar("hilbert", function()
  return lsystem {
    axiom = "+YF-XFX-FY+",
    rules = { X = "+YF-XFX-FY+", Y = "-XF+YFY+FX-" },
    angle = 90, shrink = 0.5,
  }
end)

-- Sierpinski arrowhead: 3^n segments. Odd levels end turned by 60 degrees (seed 001); the start angle
-- list turns them back so un-normalised levels also run along the x axis.
grammar("arrowhead", function()
  return lsystem {
    axiom = "XF", rules = { X = "YF-XF-Y", Y = "XF+YF+X" },
    angle = 60, shrink = 0.5, start_angle = { 0, 60 },
  }
end)

-- One Koch curve, bump to the left of its direction: 4^n segments.
grammar("koch", function()
  return lsystem { axiom = "F", rules = { F = "F+F--F+F" }, angle = 60, shrink = 1 / 3 }
end)

-- Koch snowflake: three Koch curves on a counterclockwise triangle, bumps outwards: 3*4^n segments.
-- Closed, so it is placed as drawn: from (0,0) along the triangle (0,0), (1,0), (1/2, sqrt(3)/2).
grammar("koch_snowflake", function()
  return lsystem { axiom = "F++F++F", rules = { F = "F-F++F-F" }, angle = 60, shrink = 1 / 3 }
end)

-- Gosper (flowsnake) curve: 7^n segments, scaled by 1/sqrt(7) per level.
grammar("gosper", function()
  return lsystem {
    axiom = "FX",
    rules = { X = "X+YF++YF-FX--FXFX-YF+", Y = "-FX+YFYF++YF+FX--FX-Y" },
    angle = 60, shrink = 1 / math.sqrt(7),
  }
end)

-- Six arrowhead curves of level n on the sides of a regular hexagon with unit sides (seed 001).
-- turn = 60 puts each curve's triangle inside (the hexagon); turn = -60 outside (the star).
local function arrowhead_ring(n, turn)
  local corners, x, y, heading = { { 0, 0 } }, 0, 0, 0
  for _ = 1, 6 do
    x, y = x + math.cos(math.rad(heading)), y + math.sin(math.rad(heading))
    corners[#corners + 1] = { x, y }
    heading = heading + turn
  end
  corners[#corners] = { 0, 0 } -- close exactly
  return substitute { path = polyline(corners), generator = M.arrowhead():curve { level = n }, levels = 1 }
end

function M.arrowhead_star(n) return arrowhead_ring(level_argument("arrowhead_star", n), -60) end

function M.arrowhead_hexagon(n) return arrowhead_ring(level_argument("arrowhead_hexagon", n), 60) end

-- A misspelt curve name gets a suggestion rather than "attempt to call a nil value".
local function distance(a, b)
  local row = {}
  for j = 0, #b do row[j] = j end
  for i = 1, #a do
    local diagonal, left = row[0], i
    row[0] = i
    for j = 1, #b do
      local up = row[j]
      left = math.min(up + 1, left + 1, diagonal + (a:sub(i, i) == b:sub(j, j) and 0 or 1))
      row[j], diagonal = left, up
    end
  end
  return row[#b]
end

return setmetatable(M, {
  __index = function(_, name)
    local best, best_distance = nil, 3
    for known in pairs(M) do
      local d = distance(tostring(name), known)
      if d < best_distance then best, best_distance = known, d end
    end
    error("selfsim.curves: unknown curve '" .. tostring(name) .. "'" ..
      (best and (" (did you mean '" .. best .. "'?)") or ""), 2)
  end,
})

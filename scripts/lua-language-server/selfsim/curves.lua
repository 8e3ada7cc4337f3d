---@meta selfsim.curves
-- require "selfsim.curves" (scripts/selfsim/curves.lua) for lua-language-server: the classic curves as
-- grammars, and the arrowhead compositions. See ../selfsim.lua for how this folder is laid out and checked.

---The classic curves (Irving & Segerman, Developing fractal curves, Table 1; the turtle-graphics notes on
---the Sierpinski arrowhead and the Koch snowflake).
---@class selfsim.curves
local curves = {}

---Heighway dragon: one segment becomes two, scaled by 1/sqrt(2); 2^n segments at level n.
---@return selfsim.Grammar
function curves.dragon() end

---Davis-Knuth terdragon: one segment becomes three, scaled by 1/sqrt(3); 3^n segments.
---@return selfsim.Grammar
function curves.terdragon() end

---Hilbert curve with Table 1's axiom: level n visits every cell of the 2^(n+1) grid, 4^(n+1) - 1 segments.
---@return selfsim.Grammar
function curves.hilbert() end

---Sierpinski arrowhead: 3^n segments; start_angle {0, 60} turns odd levels back onto the x axis.
---@return selfsim.Grammar
function curves.arrowhead() end

---One Koch curve, bump to the left of its direction: 4^n segments.
---@return selfsim.Grammar
function curves.koch() end

---Koch snowflake: three Koch curves on a counterclockwise triangle, bumps outwards; closed, 3*4^n segments.
---@return selfsim.Grammar
function curves.koch_snowflake() end

---Gosper (flowsnake) curve: 7^n segments, scaled by 1/sqrt(7) per level.
---@return selfsim.Grammar
function curves.gosper() end

---Six arrowhead curves of level n on a unit hexagon, their triangles outside.
---@param n integer the level, a whole number from 0
---@return selfsim.Curve
function curves.arrowhead_star(n) end

---Six arrowhead curves of level n on a unit hexagon, their triangles inside.
---@param n integer the level, a whole number from 0
---@return selfsim.Curve
function curves.arrowhead_hexagon(n) end

return curves

local a = polyline { { 0, 0 }, { 1, 0 } }
local bend = load("bend3d.vtp") -- a 3D curve
local g = group { a, bend }

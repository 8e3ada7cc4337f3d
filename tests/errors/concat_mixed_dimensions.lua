local bend = load("bend3d.vtp") -- a 3D curve
local c = concat(bend, polyline { { 0, 0 }, { 1, 0 } })

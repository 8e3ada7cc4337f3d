-- rounded: a corner needs two segments of some length to round between.
local c = polyline { { 0, 0 }, { 1, 0 }, { 1, 0 }, { 1, 1 } }
local r = c:rounded { samples = 4 }

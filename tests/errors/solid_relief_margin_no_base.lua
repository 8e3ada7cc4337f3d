local c = polygon { {0,0}, {10,0}, {10,10}, {0,10} }
local r = solid.relief(c, { height = 2, margin = 3 })

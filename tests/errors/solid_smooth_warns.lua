-- exit: 0
-- A closed mesh smoothed is checked like any solid (here one still in its curve's units); an open one is not.
local tet = mesh { points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } },
                   triangles = { { 1, 3, 2 }, { 1, 2, 4 }, { 2, 3, 4 }, { 3, 1, 4 } } }
local smooth = solid.smooth(tet, { steps = 1 })
local open = mesh { points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, triangles = { { 1, 2, 3 } } }
local quiet = solid.smooth(open, { steps = 1 })
local unchecked = solid.smooth(tet, { steps = 1, check = false })

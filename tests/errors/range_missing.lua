-- range: a field the value does not have, named.
local m = mesh { points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, triangles = { { 1, 2, 3 } } }
local ok, err = pcall(m.range, m, "tile_class")
error(err, 0)

-- develop: two triangles of one tile's fan that cross beyond their shared corner are a self-intersection too.
local levels = { polyline { { 0, 0 }, { 10, 0 } },
                 polyline { { 0, 0 }, { 1, 0.5 }, { 1.2, -0.2 }, { 0.5, 0.6 }, { 4, 3 }, { 8, 2 }, { 10, 0 } } }
develop(levels, {})

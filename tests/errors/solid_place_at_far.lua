-- At {1e308, 1e308} double precision rounds the points together: a 10 mm tetrahedron became 0 x 0 x 10 mm.
local tetra = mesh { points = { { 0, 0, 0 }, { 10, 0, 0 }, { 0, 10, 0 }, { 0, 0, 10 } },
                     triangles = { { 1, 3, 2 }, { 1, 2, 4 }, { 1, 4, 3 }, { 2, 3, 4 } } }
solid.place(tetra, { at = { 1e308, 1e308 } })

local P = bspline { points = { { 0, 0 }, { 0.5, 0.5 }, { 1, 0 } } }
local h = hoist.iterate(P, { multiplicity = 2, generations = 2, segments = { "identity", "half_turn" } })

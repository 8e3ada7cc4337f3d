-- Issue 8's size: a 4-generation, multiplicity-5 smooth self-similar curve of about a million points
-- (P sampled at flatness 5e-7: 1,606 samples, so (1,606 - 1)·5^4 + 1 = 1,003,126 points), saved as .vtp.
local P = bspline { points = { { 0, 0 }, { 0.2, 0.3 }, { 0.45, -0.25 }, { 0.7, 0.35 }, { 1, 0 } }, flatness = 5e-7 }
local h = hoist.iterate(P, { multiplicity = 5, generations = 4, boundary = "rotate", segments = "rotate" })
assert(h:points() == 1003126, h:points())
save(h, "hoist.vtp")

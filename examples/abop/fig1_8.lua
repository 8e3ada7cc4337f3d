-- ABOP Figure 1.8: the three-dimensional Hilbert curve, n = 2, delta = 90 (the book draws n = 2; a level
-- n visits every point of a (2^n)^3 lattice cube once). Yaw + -, pitch & ^ (the book's ∧), roll \ /, and
-- | turns around. The same model as examples/lsystem_hilbert3d.lua.
--   selfsim run examples/abop/fig1_8.lua --set level=3
local level = param("level", 2, { min = 0, max = 5, doc = "the level (the book: 2)" })
local hilbert = lsystem {
  axiom = "A", angle = 90,
  rules = {
    A = "B-F+CFC+F-D&F^D-F+&&CFC+F+B//",
    B = "A&F^CFB^F^D^^-F-D^|F^B|FC^F^A//",
    C = "|D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//",
    D = "|CFB-F+B|FA&F^A&&FB-F+B|FC//",
  },
}
save(hilbert:curve(level), "fig1_8.vtp") -- kept on its lattice: unit steps from the origin

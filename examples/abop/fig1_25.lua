-- ABOP Figure 1.25: a three-dimensional bush-like structure with leaves, n = 7, delta = 22.5.
--   A -> [&FL!A]/////'[&FL!A]///////'[&FL!A]     three branches per apex, 112.5 and 157.5 degrees apart
--   F -> S/////F    S -> FL    L -> ['''^^{-f+f+f-|-f+f+f}]    a leaf: a polygon pitched up (the book's ∧)
-- As the book: `!` lowers the width by one and `'` raises the colour index (point fields `width`, `color`).
-- Differs from the book: its shading and leaf colours are a rendering choice left to ParaView; the leaves
-- are a separate mesh (face field `color`: 1 stems' colour + 3 in a leaf).
--   selfsim run examples/abop/fig1_25.lua --set level=7
local level = param("level", 7)
local bush = lsystem {
  axiom = "A", angle = 22.5,
  rules = {
    A = "[&FL!A]/////'[&FL!A]///////'[&FL!A]",
    F = "S/////F",
    S = "FL",
    L = "['''^^{-f+f+f-|-f+f+f}]",
  },
}
save(bush:curve(level), "fig1_25.vtp")
save(bush:polygons(level), "fig1_25_leaves.vtp")

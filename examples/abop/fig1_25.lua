-- ABOP Figure 1.25: a three-dimensional bush-like structure with leaves, n = 7, delta = 22.5.
--   A -> [&FL!A]/////'[&FL!A]///////'[&FL!A]     three branches per apex, 112.5 and 157.5 degrees apart
--   F -> S/////F    S -> FL    L -> ['''^^{-f+f+f-|-f+f+f}]    a leaf: a polygon pitched up (the book's ∧)
-- As the book: `!` lowers the width by one and `'` raises the colour index (point fields `width`, `color`).
-- Differs from the book: the axiom is `!(n)A`, not `A`, so the stems taper from width n to 0 at the tips
-- (selfsim's turtle starts at width 1, cpfg's at its view file's width); colours and shading are left to
-- ParaView; the leaves are a separate mesh (face field `color`: the colour index, 3 more than its stem's).
--   selfsim run examples/abop/fig1_25.lua --set level=7
local level = param("level", 7, { min = 0, max = 9, doc = "the level (the book: 7)" })
local bush = lsystem {
  axiom = "!(" .. level .. ")A", angle = 22.5,
  rules = {
    A = "[&FL!A]/////'[&FL!A]///////'[&FL!A]",
    F = "S/////F",
    S = "FL",
    L = "['''^^{-f+f+f-|-f+f+f}]",
  },
}
save(bush:curve(level), "fig1_25.vtp")
save(bush:polygons(level), "fig1_25_leaves.vtp")

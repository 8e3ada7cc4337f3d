-- ABOP Figure 2.6 a-d: Honda's monopodial trees, n = 10. The trunk A shrinks by r1 and turns by the
-- divergence angle d = 137.5; lateral axes B and C by r2, alternating sides, `$` keeping each branch's
-- left side horizontal. The book's four variants (the model of examples/lsystem_tree3d.lua):
--   a  r1 = 0.9  r2 = 0.6  a0 = 45  a2 = 45      b  r1 = 0.9  r2 = 0.9  a0 = 45  a2 = 45
--   c  r1 = 0.9  r2 = 0.8  a0 = 45  a2 = 45      d  r1 = 0.9  r2 = 0.7  a0 = 30  a2 = -30
-- `variant` picks one (1 = a ... 4 = d). Differs from the book: no tropism (the book's Figure 2.6 has none;
-- examples/lsystem_tree3d.lua adds a little).
--   selfsim run examples/abop/fig2_6.lua --set variant=4
local level = param("level", 10, { min = 0, max = 16, doc = "the level (the book: 10)" })
local variant = param("variant", 1, { min = 1, max = 4, step = 1, doc = "the book's variant: 1 = a ... 4 = d" })
local v = ({ { 0.6, 45, 45 }, { 0.9, 45, 45 }, { 0.8, 45, 45 }, { 0.7, 30, -30 } })[variant]
local tree = lsystem {
  axiom = "A(1, 10)",
  define = { r1 = 0.9, r2 = v[1], a0 = v[2], a2 = v[3], d = 137.5, wr = 0.707 },
  rules = {
    "A(l, w) -> !(w) F(l) [ &(a0) B(l*r2, w*wr) ] /(d) A(l*r1, w*wr)",
    "B(l, w) -> !(w) F(l) [ -(a2) $ C(l*r2, w*wr) ] C(l*r1, w*wr)",
    "C(l, w) -> !(w) F(l) [ +(a2) $ B(l*r2, w*wr) ] B(l*r1, w*wr)",
  },
}
save(tree:curve(level), "fig2_6.vtp") -- point field `width` (from `!`) for tubes in ParaView

-- ABOP Figure 2.8 a-d: ternary trees with tropism. Each apex A grows three branches at angle a, d1 and
-- d2 apart about the stem; every F grows by lr and every width by vr each step; the branches bend
-- towards T = (0, -1, 0) by the elasticity e: selfsim's `tropism` is T times e (its length is e).
--   a  d1 = 94.74  d2 = 132.63  a = 18.95  lr = 1.109  e = 0.22  n = 6
--   b  d1 = 137.5  d2 = 137.5   a = 18.95  lr = 1.109  e = 0.14  n = 8
--   c  d1 = 112.5  d2 = 157.5   a = 22.5   lr = 1.790  e = 0.27  n = 8
--   d  d1 = 180    d2 = 252     a = 36     lr = 1.070  e = 0.40  n = 6
-- `variant` picks one (1 = a ... 4 = d), `level` another n than the book's (0: the book's).
-- The book's `F(l) : * -> F(l*lr)` and `!(w) : * -> !(w*vr)` (`*`: always) are written without a condition.
--   selfsim run examples/abop/fig2_8.lua --set variant=1
local variant = param("variant", 1, { min = 1, max = 4, step = 1, doc = "the book's variant: 1 = a ... 4 = d" })
local level = param("level", 0, { min = 0, max = 10, doc = "the level; 0: the book's n" })
local v = ({ { 94.74, 132.63, 18.95, 1.109, 0.22, 6 }, { 137.5, 137.5, 18.95, 1.109, 0.14, 8 },
             { 112.5, 157.5, 22.5, 1.790, 0.27, 8 }, { 180, 252, 36, 1.070, 0.40, 6 } })[variant]
local tree = lsystem {
  axiom = "!(1) F(200) /(45) A",
  define = { d1 = v[1], d2 = v[2], a = v[3], lr = v[4], vr = 1.732 },
  rules = {
    "A -> !(vr) F(50) [ &(a) F(50) A ] /(d1) [ &(a) F(50) A ] /(d2) [ &(a) F(50) A ]",
    "F(l) -> F(l*lr)",
    "!(w) -> !(w*vr)",
  },
  tropism = { 0, -v[5], 0 },
}
save(tree:curve(level > 0 and level or v[6]), "fig2_8.vtp") -- point field `width` for tubes in ParaView

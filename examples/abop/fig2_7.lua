-- ABOP Figure 2.7 a-d: sympodial trees (after Aono and Kunii), n = 10. Each apex forks into two
-- branches of ratios r1 and r2 at angles a1 and a2; `$` keeps each branch's left side horizontal.
--   a  r1 = 0.9  r2 = 0.7  a1 = 5   a2 = 65      b  r1 = 0.9  r2 = 0.7  a1 = 10  a2 = 60
--   c  r1 = 0.9  r2 = 0.8  a1 = 20  a2 = 50      d  r1 = 0.9  r2 = 0.8  a1 = 35  a2 = 35
-- `variant` picks one (1 = a ... 4 = d). As the book: wr = 0.707, the first fork turns 180 about the trunk.
--   selfsim run examples/abop/fig2_7.lua --set variant=2
local level = param("level", 10, { min = 0, max = 16, doc = "the level (the book: 10)" })
local variant = param("variant", 2, { min = 1, max = 4, step = 1, doc = "the book's variant: 1 = a ... 4 = d" })
local v = ({ { 0.7, 5, 65 }, { 0.7, 10, 60 }, { 0.8, 20, 50 }, { 0.8, 35, 35 } })[variant]
local tree = lsystem {
  axiom = "A(1, 10)",
  define = { r1 = 0.9, r2 = v[1], a1 = v[2], a2 = v[3], wr = 0.707 },
  rules = {
    "A(l, w) -> !(w) F(l) [ &(a1) B(l*r1, w*wr) ] /(180) [ &(a2) B(l*r2, w*wr) ]",
    "B(l, w) -> !(w) F(l) [ +(a1) $ B(l*r1, w*wr) ] [ -(a2) $ B(l*r2, w*wr) ]",
  },
}
save(tree:curve(level), "fig2_7.vtp") -- point field `width` (from `!`) for tubes in ParaView

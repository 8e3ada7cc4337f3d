-- A 3D tree with parametric branching (ABOP Figure 2.6, after Honda's monopodial trees): every module
-- carries its length l and width w; the trunk A shrinks by r1 per step and turns by the divergence angle
-- d, lateral axes B and C by r2, alternating sides, and '$' keeps each branch's left side horizontal.
-- `tropism` bends the branches down a little. A plant stands up as drawn: the trunk grows from the origin
-- up +y in unit steps. The curve's point field `width` (from '!') gives ParaView a tube radius, and
-- `branch_order` tells the trunk (0) from its branches.
--   selfsim run examples/lsystem_tree3d.lua --set level=10
local level = param("level", 10)
local tree = lsystem {
  axiom = "A(1, 10)",
  define = { r1 = 0.9, r2 = 0.6, a0 = 45, a2 = 45, d = 137.5, wr = 0.707 },
  rules = {
    "A(l, w) -> !(w) F(l) [ &(a0) B(l*r2, w*wr) ] /(d) A(l*r1, w*wr)",
    "B(l, w) -> !(w) F(l) [ -(a2) $ C(l*r2, w*wr) ] C(l*r1, w*wr)",
    "C(l, w) -> !(w) F(l) [ +(a2) $ B(l*r2, w*wr) ] B(l*r1, w*wr)",
  },
  tropism = { 0, -0.05, 0 },
}
save(tree:curve(level), "lsystem_tree3d.vtp")

-- A tree to print (ABOP Figure 2.6, as in lsystem_tree3d.lua): its branches as one tube on a grid whose
-- radius follows the turtle's width ('!' sets the point field `width`, 0.707 of its parent's at each
-- branching): `radius` mm per unit of width, none under `min_radius` mm so that the tips still print.
-- The grid's voxel is a quarter of the thinnest radius. Stood on the bed with solid.place. Level 6 passes
-- the fdm check; from level 7 some branches pass within a tenth of a millimetre of others at 80 mm, and the
-- check says where they would fuse (may fail: gaps narrower than 0.4 mm).
--   selfsim run examples/print_tree.lua --set level=8
local level = param("level", 6)
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
-- Standing up z for the printer: the turtle grows up +y.
local c = solid.size(tree:curve(level), param("size", 80.0))
local trunk = solid.tube(c, { method = "grid", radius = param("radius", 0.012), by = "width",
                              min_radius = param("min_radius", 0.5), check = false })
trunk = trunk:transform { rotate = 90, axis = { 1, 0, 0 } }
save(solid.place(trunk), "tree.3mf")

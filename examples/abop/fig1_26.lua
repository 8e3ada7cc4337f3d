-- ABOP Figure 1.26: a plant with leaves and flowers, n = 5, delta = 18. The book names its modules with
-- words; selfsim's symbols are one byte, so: P = plant, I = internode, S = seg, L = leaf, K = flower,
-- D = pedicel, W = wedge (the book's ∧ is `^`).
--   plant    -> internode+[plant+flower]--//[--leaf]internode[++leaf]-[plant flower]++plant flower
--   internode-> F seg[//&&leaf][//^^leaf]F seg        seg -> seg F seg
--   leaf     -> ['{+f-ff-f+|+f-ff-f}]                  flower -> [&&&pedicel'/wedge////wedge////wedge////wedge////wedge]
--   pedicel  -> FF                                     wedge -> ['^F][{&&&&-f+f|-f+f}]
-- Stems are the curve, leaves and petals the mesh (face field `color`: the book's colour index, from `'`).
--   selfsim run examples/abop/fig1_26.lua --set level=5
local level = param("level", 5, { min = 0, max = 8, doc = "the level (the book: 5)" })
local plant = lsystem {
  axiom = "P", angle = 18,
  rules = {
    P = "I+[P+K]--//[--L]I[++L]-[PK]++PK",
    I = "FS[//&&L][//^^L]FS",
    S = "SFS",
    L = "['{+f-ff-f+|+f-ff-f}]",
    K = "[&&&D'/W////W////W////W////W]",
    D = "FF",
    W = "['^F][{&&&&-f+f|-f+f}]",
  },
}
save(plant:curve(level), "fig1_26.vtp")
save(plant:polygons(level), "fig1_26_flowers.vtp")

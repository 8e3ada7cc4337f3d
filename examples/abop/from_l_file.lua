-- Draws one of this folder's cpfg .l files: the book's figures as the book's own program (cpfg, vlab) reads
-- them, read by lsystem.load. cpfg keeps the angle (and tropism) in its view file, not in the .l file, so
-- they are given here, as the book gives them. The strings equal the recipes' (fig1_24.lua ...) and the
-- book's texts (book_texts.lua): tests/lsystem/abop_three_ways.py checks it.
--   selfsim run examples/abop/from_l_file.lua --set file=fig2_6a
--   selfsim run examples/abop/from_l_file.lua --set file=fig1_31c --set level=20
local views = { -- what each file's figure takes from the book beside its .l file
  fig1_8 = { angle = 90 }, fig1_25 = { angle = 22.5 }, fig1_26 = { angle = 18 }, fig1_27 = { angle = 25.7, seed = 1 },
  fig1_24a = { angle = 25.7 }, fig1_24b = { angle = 20 }, fig1_24c = { angle = 22.5 },
  fig1_24d = { angle = 20 }, fig1_24e = { angle = 25.7 }, fig1_24f = { angle = 22.5 },
  fig1_31a = { angle = 22.5 }, fig1_31b = { angle = 22.5 }, fig1_31c = { angle = 25.75 },
  fig1_31d = { angle = 25.75 }, fig1_31e = { angle = 22.5 },
  fig2_6a = {}, fig2_6b = {}, fig2_6c = {}, fig2_6d = {},
  fig2_7a = {}, fig2_7b = {}, fig2_7c = {}, fig2_7d = {},
  fig2_8a = { tropism = { 0, -0.22, 0 } }, fig2_8b = { tropism = { 0, -0.14, 0 } },
  fig2_8c = { tropism = { 0, -0.27, 0 } }, fig2_8d = { tropism = { 0, -0.40, 0 } },
}
local names = {}
for name in pairs(views) do names[#names + 1] = name end
table.sort(names)
local file = param("file", "fig2_6a", { choices = names, doc = "the .l file of this folder (without .l)" })
local level = param("level", 0, { min = 0, max = 30, doc = "the level; 0: the file's derivation length" })

local g = lsystem.load(file .. ".l", views[file])
local n = level > 0 and level or nil
save(g:curve(n), file .. ".vtp") -- point fields `width` and `color` where the model sets them
if file == "fig1_25" or file == "fig1_26" then save(g:polygons(n), file .. "_leaves.vtp") end

-- ABOP Figure 1.31 a-e (after Hogeweg and Hesper): context-sensitive plants, #ignore: + - F.
-- The states 0 and 1 pass signals along the branches; each rule reads the state on either side. A left
-- context skips completed branches and steps out of the module's own branch past its '['; a right context
-- skips branches, and the end of the module's own branch ends it (ABOP 1.8). The book's `*<+>* -> -` and
-- `*<->* -> +` (swap the turns every step) are written context-free, as they mean the same.
--   figure  n   delta  axiom   successors of 0<0>0 0<0>1 0<1>0 0<1>1 1<0>0 1<0>1 1<1>0 1<1>1
--   a       30  22.5   F1F1F1  0 1[+F1F1] 1 1 0 1F1 0 0
--   b       30  22.5   F1F1F1  1 1[-F1F1] 1 1 0 1F1 1 0
--   c       26  25.75  F1F1F1  0 1 0 1[+F1F1] 0 1F1 0 0
--   d       24  25.75  F0F1F1  1 0 0 1F1 1 1[+F1F1] 1 0
--   e       26  22.5   F1F1F1  0 1[-F1F1] 1 1 0 1F1 1 0
-- `level` draws every plant at that level instead of the book's n (0, the default: the book's);
-- `strings = 1` prints each plant's string (`a<TAB>string`) at that level instead of drawing, which
-- tests/lsystem/abop_context_check.py compares with its own rewriter.
--   selfsim run examples/abop/fig1_31.lua
local sheet = require "selfsim.sheet"
local level = param("level", 0, { min = 0, max = 40, doc = "every plant's level; 0: the book's n" })
local strings = param("strings", 0, { min = 0, max = 1, doc = "1: print the strings instead of drawing" })

local contexts = { "0 < 0 > 0", "0 < 0 > 1", "0 < 1 > 0", "0 < 1 > 1", "1 < 0 > 0", "1 < 0 > 1", "1 < 1 > 0",
                   "1 < 1 > 1" }
local figures = {
  { name = "a", n = 30, angle = 22.5, axiom = "F1F1F1", to = { "0", "1[+F1F1]", "1", "1", "0", "1F1", "0", "0" } },
  { name = "b", n = 30, angle = 22.5, axiom = "F1F1F1", to = { "1", "1[-F1F1]", "1", "1", "0", "1F1", "1", "0" } },
  { name = "c", n = 26, angle = 25.75, axiom = "F1F1F1", to = { "0", "1", "0", "1[+F1F1]", "0", "1F1", "0", "0" } },
  { name = "d", n = 24, angle = 25.75, axiom = "F0F1F1", to = { "1", "0", "0", "1F1", "1", "1[+F1F1]", "1", "0" } },
  { name = "e", n = 26, angle = 22.5, axiom = "F1F1F1", to = { "0", "1[-F1F1]", "1", "1", "0", "1F1", "1", "0" } },
}
local plants = {}
for i, f in ipairs(figures) do
  local rules = {}
  for k, context in ipairs(contexts) do rules[k] = context .. " -> " .. f.to[k] end
  rules[#rules + 1] = "+ -> -"
  rules[#rules + 1] = "- -> +"
  local g = lsystem { axiom = f.axiom, angle = f.angle, ignore = "+-F", rules = rules }
  local n = level > 0 and level or f.n
  if strings == 1 then
    print(f.name .. "\t" .. g:string(n))
  else
    plants[i] = { g:curve(n), stroke = "#1d3557" }
  end
end
if strings ~= 1 then
  local s = sheet.grid(plants, { columns = 5 })
  save(s, "fig1_31.svg", { stroke_width = 0.5 })
  save(s, "fig1_31.vtp") -- cell field `curve`: which plant (1 = a ... 5 = e)
end

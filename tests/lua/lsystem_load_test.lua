-- lsystem.load (kernels/lsystem/cpfg_file.h, book_text.h): cpfg's .l files give the same strings as the same
-- grammars written in lsystem{} and in the book's notation.

local function same(a, b, levels, what)
  for _, n in ipairs(levels) do
    assert(a:string(n) == b:string(n), what .. ": level " .. n .. " differs")
  end
end

-- Figure 2.6: #include of the constants beside it, #define used by derivation length, comments, -->.
local tree = lsystem.load("lsystem_load/tree.l")
local own = lsystem {
  axiom = "A(1,10)",
  define = { r1 = 0.9, r2 = 0.6, a0 = 45, a2 = 45, d = 137.5, wr = 0.707, STEPS = 10 },
  rules = {
    "A(l,w) -> !(w)F(l)[&(a0)B(l*r2,w*wr)]/(d)A(l*r1,w*wr)",
    "B(l,w) -> !(w)F(l)[-(a2)$C(l*r2,w*wr)]C(l*r1,w*wr)",
    "C(l,w) -> !(w)F(l)[+(a2)$B(l*r2,w*wr)]B(l*r1,w*wr)",
  },
  ignore = "",
}
same(tree, own, { 1, 5 }, "tree.l")
assert(tree:string() == own:string(10), "derivation length: STEPS is the default level")

-- Figure 1.31a: consider: 0 1 means every other symbol is ignored by the contexts.
local fig = lsystem.load("lsystem_load/fig131a.l", { angle = 22.5 })
local rules131a = [[
ω : F1F1F1
p1 : 0 < 0 > 0 → 0
p2 : 0 < 0 > 1 → 1[+F1F1]
p3 : 0 < 1 > 0 → 1
p4 : 0 < 1 > 1 → 1
p5 : 1 < 0 > 0 → 0
p6 : 1 < 0 > 1 → 1F1
p7 : 1 < 1 > 0 → 0
p8 : 1 < 1 > 1 → 0
p9 : * < + > * → −
p10 : * < − > * → +
n = 30, δ = 22.5°
]]
local book = lsystem.book("#ignore: +-F\n" .. rules131a)
same(fig, book, { 3, 12, 30 }, "fig131a.l")
assert(fig:string() == book:string(), "derivation length 30")
-- Without consider: (nothing ignored) the contexts see F and the turns and the strings differ: consider: is read.
assert(lsystem.book(rules131a):string(12) ~= fig:string(12))

-- Probabilities after the successor; the seed is the table's.
local st = lsystem.load("lsystem_load/stochastic.l", { seed = 5 })
local own_st = lsystem {
  axiom = "F",
  rules = { "F -> F[+F]F[-F]F : 0.33", "F -> F[+F]F : 0.33", "F -> F[-F]F : 0.34" },
  seed = 5,
  ignore = "",
  max_depth = 2,
}
same(st, own_st, { 1, 4 }, "stochastic.l")

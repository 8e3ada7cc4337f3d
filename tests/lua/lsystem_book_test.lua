-- lsystem.book (kernels/lsystem/book_text.h): a grammar written as The Algorithmic Beauty of Plants prints it
-- gives the same strings as the same grammar written in lsystem{}'s own syntax.

local function same(book, own, levels, what)
  for _, n in ipairs(levels) do
    local a, b = book:string(n), own:string(n)
    assert(a == b, what .. ": level " .. n .. " differs (" .. #a .. " vs " .. #b .. " bytes)")
  end
end

-- Figure 1.24a: ω, a label, the book's arrow, n and δ on one line.
local fig124a = lsystem.book [[
  n = 5, δ = 25.7°
  ω : F
  p1 : F → F[+F]F[−F]F
]]
local own124a = lsystem { axiom = "F", rules = { F = "F[+F]F[-F]F" }, angle = 25.7 }
same(fig124a, own124a, { 0, 1, 3, 5 }, "Figure 1.24a")
assert(fig124a:string() == own124a:string(5), "n = 5 is the default level")
assert(fig124a:count() == own124a:count(5))

-- Figure 2.6: #define, conditions written '*', '&' and the book's '∧'-free rules, derivation length.
local fig26 = lsystem.book [[
#define r1 0.9
#define r2 0.6
#define a0 45
#define a2 45
#define d 137.5
#define wr 0.707
ω : A(1,10)
p1 : A(l,w) : * → !(w)F(l)[&(a0)B(l*r2,w*wr)]/(d)A(l*r1,w*wr)
p2 : B(l,w) : * → !(w)F(l)[-(a2)$C(l*r2,w*wr)]C(l*r1,w*wr)
p3 : C(l,w) : * → !(w)F(l)[+(a2)$B(l*r2,w*wr)]B(l*r1,w*wr)
derivation length: 10
]]
local own26 = lsystem {
  axiom = "A(1,10)",
  define = { r1 = 0.9, r2 = 0.6, a0 = 45, a2 = 45, d = 137.5, wr = 0.707 },
  rules = {
    "A(l,w) -> !(w)F(l)[&(a0)B(l*r2,w*wr)]/(d)A(l*r1,w*wr)",
    "B(l,w) -> !(w)F(l)[-(a2)$C(l*r2,w*wr)]C(l*r1,w*wr)",
    "C(l,w) -> !(w)F(l)[+(a2)$B(l*r2,w*wr)]B(l*r1,w*wr)",
  },
  ignore = "",
}
same(fig26, own26, { 1, 4, 8 }, "Figure 2.6")
assert(fig26:string() == own26:string(10), "derivation length 10 is the default level")

-- Figure 1.31a: contexts, #ignore, ABOP's '*' contexts and the typeset minus.
local fig131a = lsystem.book [[
#ignore: +-F
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
local own131a = lsystem {
  axiom = "F1F1F1",
  rules = [[
0 < 0 > 0 -> 0
0 < 0 > 1 -> 1[+F1F1]
0 < 1 > 0 -> 1
0 < 1 > 1 -> 1
1 < 0 > 0 -> 0
1 < 0 > 1 -> 1F1
1 < 1 > 0 -> 0
1 < 1 > 1 -> 0
+ -> -
- -> +
]],
  ignore = "+-F",
  angle = 22.5,
}
same(fig131a, own131a, { 1, 5, 15, 30 }, "Figure 1.31a")

-- Probabilities where the book puts them (at the arrow, before it) and after the successor.
local book_choice = lsystem.book([[
ω : F
p1 : F →(0.33) F[+F]F[-F]F
p2 : F (0.33) --> F[+F]F
p3 : F -> F[-F]F : 0.34
]], { seed = 7 })
local own_choice = lsystem {
  axiom = "F",
  rules = { "F -> F[+F]F[-F]F : 0.33", "F -> F[+F]F : 0.33", "F -> F[-F]F : 0.34" },
  seed = 7,
  ignore = "",
}
same(book_choice, own_choice, { 1, 3, 5 }, "stochastic")

-- '=' in a condition is the book's equality; the table gives what the text does not.
local cond = lsystem.book([[
ω : A(0)
A(t) : t = 2 → F A(t+1)
A(t) : t < 2 → A(t+1)
]], { angle = 60 })
assert(cond:string(2) == "A(2)", cond:string(2))
assert(cond:string(3) == "FA(3)", cond:string(3))

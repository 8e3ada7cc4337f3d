-- The models of this folder's figures as The Algorithmic Beauty of Plants prints them, for lsystem.book:
--   local g = lsystem.book(require("book_texts").fig1_24a)
-- Keyed as the .l files beside them (fig2_6a.l ...). tests/lsystem/abop_three_ways.py checks that each gives
-- the same strings as the recipe's lsystem{} and as its .l file. Where a recipe differs from the book, the
-- text follows the recipe (its header says why): 1.25's axiom !(7)A tapers the stems; 1.26's word-named
-- modules are one letter each; the book's ’ is written '.
local t = {}

local fig1_24 = {
  a = { "n = 5, δ = 25.7°", "ω : F", "p1 : F → F[+F]F[−F]F" },
  b = { "n = 5, δ = 20°", "ω : F", "p1 : F → F[+F]F[−F][F]" },
  c = { "n = 4, δ = 22.5°", "ω : F", "p1 : F → FF−[−F+F+F]+[+F−F−F]" },
  d = { "n = 7, δ = 20°", "ω : X", "p1 : X → F[+X]F[−X]+X", "p2 : F → FF" },
  e = { "n = 7, δ = 25.7°", "ω : X", "p1 : X → F[+X][−X]FX", "p2 : F → FF" },
  f = { "n = 5, δ = 22.5°", "ω : X", "p1 : X → F−[[X]+X]+F[+FX]−X", "p2 : F → FF" },
}
for k, lines in pairs(fig1_24) do t["fig1_24" .. k] = table.concat(lines, "\n") end

t.fig1_8 = [[
n = 2, δ = 90°
ω : A
p1 : A → B−F+CFC+F−D&F∧D−F+&&CFC+F+B//
p2 : B → A&F∧CFB∧F∧D∧∧−F−D∧|F∧B|FC∧F∧A//
p3 : C → |D∧|F∧B−F+C∧F∧A&&FA&F∧C+F+B∧F∧D//
p4 : D → |CFB−F+B|FA&F∧A&&FB−F+B|FC//
]]

t.fig1_25 = [[
n = 7, δ = 22.5°
ω : !(7)A
p1 : A → [&FL!A]/////'[&FL!A]///////'[&FL!A]
p2 : F → S/////F
p3 : S → FL
p4 : L → ['''∧∧{−f+f+f−|−f+f+f}]
]]

t.fig1_26 = [[
n = 5, δ = 18°
ω : P
p1 : P → I+[P+K]−−//[−−L]I[++L]−[PK]++PK
p2 : I → FS[//&&L][//∧∧L]FS
p3 : S → SFS
p4 : L → ['{+f−ff−f+|+f−ff−f}]
p5 : K → [&&&D'/W////W////W////W////W]
p6 : D → FF
p7 : W → ['∧F][{&&&&−f+f|−f+f}]
]]

t.fig1_27 = [[
n = 5, δ = 25.7°
ω : F
p1 : F →(0.33) F[+F]F[−F]F
p2 : F →(0.33) F[+F]F
p3 : F →(0.34) F[−F]F
]]

-- 1.31 a-e: the successors of 0<0>0 0<0>1 0<1>0 0<1>1 1<0>0 1<0>1 1<1>0 1<1>1, as the recipe's table.
local fig1_31 = {
  a = { "30", "22.5", "F1F1F1", { "0", "1[+F1F1]", "1", "1", "0", "1F1", "0", "0" } },
  b = { "30", "22.5", "F1F1F1", { "1", "1[−F1F1]", "1", "1", "0", "1F1", "1", "0" } },
  c = { "26", "25.75", "F1F1F1", { "0", "1", "0", "1[+F1F1]", "0", "1F1", "0", "0" } },
  d = { "24", "25.75", "F0F1F1", { "1", "0", "0", "1F1", "1", "1[+F1F1]", "1", "0" } },
  e = { "26", "22.5", "F1F1F1", { "0", "1[−F1F1]", "1", "1", "0", "1F1", "1", "0" } },
}
local contexts = { "0 < 0 > 0", "0 < 0 > 1", "0 < 1 > 0", "0 < 1 > 1", "1 < 0 > 0", "1 < 0 > 1", "1 < 1 > 0",
                   "1 < 1 > 1" }
for k, f in pairs(fig1_31) do
  local lines = { "#ignore: + − F", "n = " .. f[1] .. ", δ = " .. f[2] .. "°", "ω : " .. f[3] }
  for i, c in ipairs(contexts) do lines[#lines + 1] = "p" .. i .. " : " .. c .. " → " .. f[4][i] end
  lines[#lines + 1] = "p9 : * < + > * → −"
  lines[#lines + 1] = "p10 : * < − > * → +"
  t["fig1_31" .. k] = table.concat(lines, "\n")
end

-- 2.6 a-d: r2, a0, a2 of each variant.
local fig2_6 = { a = { 0.6, 45, 45 }, b = { 0.9, 45, 45 }, c = { 0.8, 45, 45 }, d = { 0.7, 30, -30 } }
for k, v in pairs(fig2_6) do
  t["fig2_6" .. k] = ([[
#define r1 0.9
#define r2 %s
#define a0 %s
#define a2 %s
#define d 137.5
#define wr 0.707
ω : A(1,10)
p1 : A(l,w) : * → !(w)F(l)[&(a0)B(l*r2,w*wr)]/(d)A(l*r1,w*wr)
p2 : B(l,w) : * → !(w)F(l)[−(a2)$C(l*r2,w*wr)]C(l*r1,w*wr)
p3 : C(l,w) : * → !(w)F(l)[+(a2)$B(l*r2,w*wr)]B(l*r1,w*wr)
derivation length: 10
]]):format(v[1], v[2], v[3])
end

-- 2.7 a-d: r2, a1, a2 of each variant.
local fig2_7 = { a = { 0.7, 5, 65 }, b = { 0.7, 10, 60 }, c = { 0.8, 20, 50 }, d = { 0.8, 35, 35 } }
for k, v in pairs(fig2_7) do
  t["fig2_7" .. k] = ([[
#define r1 0.9
#define r2 %s
#define a1 %s
#define a2 %s
#define wr 0.707
ω : A(1,10)
p1 : A(l,w) : * → !(w)F(l)[&(a1)B(l*r1,w*wr)]/(180)[&(a2)B(l*r2,w*wr)]
p2 : B(l,w) : * → !(w)F(l)[+(a1)$B(l*r1,w*wr)][−(a2)$B(l*r2,w*wr)]
derivation length: 10
]]):format(v[1], v[2], v[3])
end

-- 2.8 a-d: d1, d2, a, lr, n of each variant (the elasticity is the tropism option's length).
local fig2_8 = { a = { 94.74, 132.63, 18.95, 1.109, 6 }, b = { 137.5, 137.5, 18.95, 1.109, 8 },
                 c = { 112.5, 157.5, 22.5, 1.790, 8 }, d = { 180, 252, 36, 1.070, 6 } }
for k, v in pairs(fig2_8) do
  t["fig2_8" .. k] = ([[
#define d1 %s
#define d2 %s
#define a %s
#define lr %s
#define vr 1.732
ω : !(1)F(200)/(45)A
p1 : A : * → !(vr)F(50)[&(a)F(50)A]/(d1)[&(a)F(50)A]/(d2)[&(a)F(50)A]
p2 : F(l) : * → F(l*lr)
p3 : !(w) : * → !(w*vr)
derivation length: %s
]]):format(v[1], v[2], v[3], v[4], v[5])
end

return t

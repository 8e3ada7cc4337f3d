local g = lsystem { axiom = "A(1)", rules = [[
#define r1 0.9
A(l) -> F(l) A(l*r1)
]] }

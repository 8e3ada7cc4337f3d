-- The parametric peer comparison (issue 24): ABOP's binary tree A(x) -> F(x) [+(30) A(x*0.5)] [-(30) A(x*0.5)]
-- at level 17 (1,048,569 modules; 131,071 segments), derived all the way to vertices.
local n = param("level", 17)
local g = lsystem { axiom = "A(1)", rules = { "A(x) -> F(x) [+(30) A(x*0.5)] [-(30) A(x*0.5)]" } }
local c = g:curve(n)
assert(c:segments() == 2 ^ n - 1)

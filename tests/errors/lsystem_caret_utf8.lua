-- the column counts characters: «» are two, not the four bytes they take
local g = lsystem { axiom = "A(1)", rules = { "A(x) -> «» F(y)" } }

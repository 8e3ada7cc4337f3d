-- args: --max-points 1e6
-- polygons draw through the interpretation as curves do: counted and refused before any of it is drawn
local g = lsystem { axiom = "B A(1)", rules = { "B -> B" }, interpretation = { "A(x) : x > 0 -> { F . A(x) A(x) }" }, max_depth = 40 }
g:polygons(3)

-- args: --max-points 1e6
-- polygons draw through the interpretation as curves do: counted and refused before any of it is drawn
local g = lsystem { axiom = "B A", rules = { "B -> B" }, interpretation = { "A -> { F . A A }" }, max_depth = 40 }
g:polygons(3)

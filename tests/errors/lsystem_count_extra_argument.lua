-- g:count(level) takes the level alone.
local g = lsystem { axiom = "F", rules = { F = "F+F" }, angle = 90 }
print(g:count(3, "segments"))

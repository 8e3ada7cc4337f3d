-- g:curve(5, false): the second argument was ignored, so the plant was still normalised; now an error naming
-- what curve takes (issue 38).
local g = lsystem { axiom = "X", rules = { X = "F[+X]F[-X]+X", F = "FF" }, angle = 20 }
local c = g:curve(5, false)

-- A turtle width far wider than the drawing (a 1e300 trunk on a curve shrunk to unit size): refused naming
-- the point, the width it would draw given as a number (it was printed with hundreds of digits).
local c = lsystem { axiom = "!(1)F!(1e300)F", rules = {}, angle = 25 }:curve(0)
save(c, "w.svg")

-- develop: a grammar whose level 0 draws nothing (the classic Hilbert axiom X has no F).
develop(lsystem { axiom = "X", rules = { X = "+YF-XFX-FY+", Y = "-XF+YFY+FX-" }, angle = 90 }, { levels = 3 })

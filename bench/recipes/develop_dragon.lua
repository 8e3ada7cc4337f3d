-- Issue 9's sizes: the developing dragon by route 1 at `levels` with `smooth` Loop rounds, thickened, saved
-- as .stl (level 11 with 3 rounds: 819,184 triangles; level 17 with 2: 13,631,672).
local curves = require "selfsim.curves"
local s = develop(curves.dragon(), { levels = param("levels", 11), smooth = param("smooth", 3),
                                     thickness = 0.03, thickness_rate = 0.85 })
print(s:faces())
save(s, "dragon.stl")

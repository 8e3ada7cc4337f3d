-- What `selfsim preview` is timed on (bench/README.md, "Previews"): the developing dragon at `levels` with
-- `smooth` Loop rounds, saved as its final surface (levels 11, smooth 4: 1,572,096 triangles, 95 MB .vtp)
-- and as its growth, one step per level (.pvd).
local curves = require "selfsim.curves"
local s = develop(curves.dragon(), { levels = param("levels", 11), smooth = param("smooth", 4) })
print(s:faces())
save(s, "surface.vtp")
save(s:levels(), "growth.pvd")

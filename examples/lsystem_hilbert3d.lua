-- ABOP's three-dimensional Hilbert curve (Figure 1.8): the 3D turtle's yaw (+ -), pitch (& ^), roll (\ /)
-- and turn-around (|) at 90 degrees. Level n visits every point of a (2^n)^3 lattice cube exactly once.
--   selfsim run examples/lsystem_hilbert3d.lua --set level=4
local level = param("level", 3)
local hilbert = lsystem {
  axiom = "A", angle = 90,
  rules = {
    A = "B-F+CFC+F-D&F^D-F+&&CFC+F+B//",
    B = "A&F^CFB^F^D^^-F-D^|F^B|FC^F^A//",
    C = "|D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//",
    D = "|CFB-F+B|FA&F^A&&FB-F+B|FC//",
  },
}
save(hilbert:curve(level), "lsystem_hilbert3d.vtp") -- 3D: kept on its lattice, heading +y

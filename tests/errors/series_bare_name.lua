-- A bare .series: ParaView picks its reader from the extension before '.series'.
local c = lsystem { axiom = "F", rules = { F = "F+F" }, angle = 90 }:curve { level = 2 }
save(c:levels(), "growth.series")

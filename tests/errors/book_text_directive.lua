local g = lsystem.book [[
ω : F
#include "leaf.l"
]]

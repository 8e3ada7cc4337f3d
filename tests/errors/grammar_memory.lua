-- args: --max-memory 32M
-- grammars keep their rules in C++ memory: counted against --max-memory like Lua strings
local rule, keep = string.rep("F", (1 << 20) - 2), {}
for i = 1, 100 do keep[i] = lsystem { axiom = "F", rules = { F = rule } } end

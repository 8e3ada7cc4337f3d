-- args: --max-memory 16M
-- out of memory in table constructors still names the line
local t = {}
for i = 1, 1e7 do t[i] = {} end

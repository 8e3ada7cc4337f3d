-- A method given an argument it does not take is an error naming what it takes, not an argument ignored.
local c = polyline { { 0, 0 }, { 3, 4 } }
print(c:length(2))

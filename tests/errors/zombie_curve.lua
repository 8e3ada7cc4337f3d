local zombie
do
  local c = polyline { { 0, 0 }, { 1, 0 } }
  setmetatable({}, { __gc = function() zombie = c end })
end
collectgarbage(); collectgarbage()
save(zombie, "zombie.svg")

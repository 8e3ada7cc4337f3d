local curves = require "selfsim.curves"
for _, name in ipairs { "dragon", "terdragon", "hilbert", "arrowhead", "koch", "koch_snowflake", "gosper" } do
  local c = curves[name]():curve { level = 2 }
  print(name, c:points(), c:length())
end
save(curves.arrowhead_star(1), "star.vtp")
print(pcall(curves.dragn))

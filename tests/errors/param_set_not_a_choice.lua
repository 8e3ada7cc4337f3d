-- args: --set mode=rotat
local mode = param("mode", "clamp", { choices = { "clamp", "repeat", "rotate" } })

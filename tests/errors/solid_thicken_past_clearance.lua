-- exit: 0
local ball = volume.sphere { center = {0,0,0}, radius = 1 }
local s = exclusion.surface { region = ball, start = { {-.6,-.4,0}, {.6,-.4,0}, {0,.6,0} }, radius = 0.2, levels = 1 }
local below = solid.thicken(s, { thickness = 0.19, check = false })   -- below the clearance 0.2: nothing said
local past = solid.thicken(s, { thickness = 0.3, check = false })

-- the warning comes first; the recipe then stops itself so that no file is written
local s = volume.sphere { center = {0,0,0}, radius = 1, voxel = 0.2 }
exclusion.surface { region = s, start = { {-.5,-.3,0}, {.5,-.3,0}, {0,.5,0} }, radius = 0.2, levels = 3 }
error("stop")

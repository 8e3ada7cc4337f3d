local box = volume.box { min = {0,0,0}, max = {1,1,1} }
exclusion.surface { region = box, start = { {.2,.2,.5}, {.8,.2,.5}, {.5,.8,.5} }, radius = 0.1, levels = 2, walls = "grids" }

local l = volume.difference { volume.box { min = {0,0,0}, max = {2,2,1} }, volume.box { min = {1,1,-1}, max = {3,3,2} } }
exclusion.surface { region = l, start = { {1.8,.5,.5}, {.5,1.8,.5}, {.3,.3,.5} }, radius = 0.1, levels = 2 }

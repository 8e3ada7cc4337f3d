local box = volume.box { min = {1e15,1e15,1e15}, max = {1e15+1,1e15+1,1e15+1} }
exclusion.surface { region = box, start = { {1e15+.2,1e15+.2,1e15+.5}, {1e15+.8,1e15+.2,1e15+.5}, {1e15+.5,1e15+.8,1e15+.5} }, radius = 0.1, levels = 2 }

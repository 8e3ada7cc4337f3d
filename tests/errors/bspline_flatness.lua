local P = catmull_rom { points = { { 0, 0 }, { 0.5, 0.5 }, { 1, 0 } }, flatness = 0 }

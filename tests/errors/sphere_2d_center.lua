local ball = volume.sphere { center = { 1, 2 }, radius = 1 }

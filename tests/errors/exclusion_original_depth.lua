-- Bowyer's own rule splits level by level: depth order is refused by name.
exclusion.curve { region = polygon { {0,0}, {1,0}, {1,1}, {0,1} }, start = polyline { {0,0}, {1,1} },
                  radius = 0.1, levels = 3, exclusion = "original", order = "depth" }

local s = develop({ polyline { { 0, 0 }, { 1, 0 } }, polyline { { 0, 0 }, { 0.5, 0.5 }, { 1, 0 } } }, { levels = 1 })

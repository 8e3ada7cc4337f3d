local s = develop({ polyline { { 0, 0 }, { 1, 0 } } })

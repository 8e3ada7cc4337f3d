local s = develop({ polyline { { 0, 0 }, { 0, 0 } }, polyline { { 0, 0 }, { 0, 0 }, { 0, 0 } } })

local h = hoist.onto(polyline { { 0, 0 }, { 1, 0 } }, polyline { { 0, 0 }, { 0.5, 0.5 } })

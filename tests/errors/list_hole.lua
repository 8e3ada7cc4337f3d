local c = polyline { { 0, 0 }, [3] = { 1, 0 } }

-- finite points whose extent overflows: no "inf" or "nan" in a viewBox
save(polyline { { -1e308, 0 }, { 1e308, 0 } }, "x.svg")

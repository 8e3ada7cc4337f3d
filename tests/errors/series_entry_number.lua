local a = polyline { { 0, 0 }, { 1, 0 } }
save({ a, 2, a }, "morph.vtp.series")

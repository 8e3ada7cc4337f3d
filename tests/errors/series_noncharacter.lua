local a = polyline { { 0, 0 }, { 1, 0 } }
save({ a, a }, "growth\xef\xbf\xbf.pvd")

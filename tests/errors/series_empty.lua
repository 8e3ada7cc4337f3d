save({}, "morph.pvd")

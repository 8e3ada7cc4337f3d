save({}, "g.svg")

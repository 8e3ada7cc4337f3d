-- develop: an empty list of levels (and a grammar whose axiom draws nothing) is refused, not a crash.
develop({}, {})

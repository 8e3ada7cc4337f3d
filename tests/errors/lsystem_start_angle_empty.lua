-- An empty list would read as "not given" (the turtle's default heading): refused.
lsystem { axiom = "F", start_angle = {} }

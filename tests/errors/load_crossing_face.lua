-- A concave OBJ face that crosses itself: no triangles can cover it once, so it is refused by name.
load("crossing_face.obj")

load("load_bad_face.obj")

load("load_not_a_mesh.ply")

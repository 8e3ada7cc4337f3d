volume.mesh("nowhere.stl")

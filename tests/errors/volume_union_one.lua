volume.union { volume.box { min = {0,0,0}, max = {1,1,1} } }

local box = volume.box { min = {0,0,0}, max = {1e-300,1e-300,1e-300} }
save(box, "region.vdb")

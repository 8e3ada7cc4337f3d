local box = volume.box { min = {0,0,0}, max = {1,1,1}, voxel = 1e-7 }
save(box, "region.vdb")

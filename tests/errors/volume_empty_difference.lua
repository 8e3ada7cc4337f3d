local b = volume.box { min = {0,0,0}, max = {1,1,1} }
save(volume.difference { b, volume.box { min = {-1,-1,-1}, max = {2,2,2} } }, "nothing.vtp")

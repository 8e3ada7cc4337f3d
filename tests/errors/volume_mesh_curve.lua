volume.mesh(polyline { {0,0}, {1,1} })

solid.place(polyline { {0,0}, {1,0} })

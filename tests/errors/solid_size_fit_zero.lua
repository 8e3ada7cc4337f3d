solid.size(polyline { {0,0}, {1,0}, {1,1} }, { fit = {0,0,0} })

solid.relief(polygon { {0,0}, {10,0}, {10,10} }, { height = 0 })

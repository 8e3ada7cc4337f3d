local c = concat({ { 0, 0 } })

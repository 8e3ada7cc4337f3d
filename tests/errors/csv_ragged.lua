save({ { "x", "y" }, { 1, 2, 3 } }, "table.csv")

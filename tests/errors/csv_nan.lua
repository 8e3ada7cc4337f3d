save({ { "x" }, { 0/0 } }, "table.csv")

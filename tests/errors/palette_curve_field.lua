-- odd_fields.vtp numbers its paths 1.5 and 2 in its 'curve' cell field
save(load("odd_fields.vtp"), "p.svg", { stroke = { "red", "blue" } })

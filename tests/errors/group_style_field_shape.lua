-- odd_fields.vtp holds a 'color' cell field of two components: not a stroke colour
local odd = load("odd_fields.vtp")
local g = group { odd, { polyline { { 0, 0 }, { 1, 0 } }, stroke = "red" } }

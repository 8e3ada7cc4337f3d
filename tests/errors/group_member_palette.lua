-- a member has one style; palettes belong to save()
local a = polyline { { 0, 0 }, { 1, 0 } }
local g = group { { a, stroke = { "red", "blue" } } }

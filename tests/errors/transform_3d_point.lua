local c = polyline { { 0, 0 }, { 1, 0 } }:transform { translate = { 1, 2, 0 } }

polyline { { 0, 0 }, { 1, 1 } }:transform { rotation = 90 }

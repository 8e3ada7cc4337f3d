local s = develop({ polyline { { 0, 0 }, { 1, 0 }, { 0, 0 } },
                  polyline { { 0, 0 }, { 0.5, 0.1 }, { 1, 0 }, { 0.5, -0.1 }, { 0, 0 } } }, { smooth = 1 })

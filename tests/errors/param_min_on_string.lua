local mode = param("mode", "clamp", { min = 1 })

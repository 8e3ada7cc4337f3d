local mode = param("mode", true, { min = 0 })

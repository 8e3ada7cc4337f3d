local mode = param("mode", "clamp", { choices = {} })

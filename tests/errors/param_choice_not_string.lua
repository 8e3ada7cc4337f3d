local mode = param("mode", "clamp", { choices = { "clamp", 3 } })

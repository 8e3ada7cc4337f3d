local mode = param("mode", "clamp", { choices = { "repeat", "rotate" } })

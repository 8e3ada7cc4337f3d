param("level\0x", 3)

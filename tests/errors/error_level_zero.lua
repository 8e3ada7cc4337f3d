-- error(msg, 0) carries no location: the recipe line is added, so every error names it
error("no position given", 0)

-- a module name too long for the filesystem is not found, not an internal error
require(string.rep("m", 300))

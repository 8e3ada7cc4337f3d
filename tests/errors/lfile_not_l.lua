local g = lsystem.load("bad_rule.lua")

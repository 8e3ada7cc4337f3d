-- A misspelt DSL table, indexed: the closest global.
local c = exclusio.curve { generator = { { 0, 0 }, { 1, 0 } } }

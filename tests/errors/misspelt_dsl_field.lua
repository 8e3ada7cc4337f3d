-- A misspelt function of a DSL table names the table's closest function.
local c = exclusion.curv { generator = { { 0, 0 }, { 1, 0 } } }

-- A local that shadows a DSL table is the recipe's own: no suggestion from the global of that name.
local exclusion = {}
local c = exclusion.curv { generator = { { 0, 0 }, { 1, 0 } } }

-- Prints every name the interpreter gives recipes, one per line, for check_meta.py to compare with the
-- lua-language-server definitions in scripts/lua-language-server/:
--   global NAME          every global (check_meta.py leaves out standard Lua's)
--   field TABLE.NAME     every field of a global table that is not standard Lua's
--   module MODULE        every module named in --set "modules=a b" (the DSL's scripts/ folder holds them)
--   export MODULE NAME   every field of that module's table
--   type TYPE            a value type built below, and  method TYPE NAME  for each of its methods
-- Value metatables are locked (getmetatable gives a string), so the methods come from the error the
-- interpreter raises for a method a type lacks, which lists all of them ("...; its methods: a, b").

local standard_tables = {
  coroutine = true, debug = true, io = true, math = true, os = true, package = true, string = true,
  table = true, utf8 = true, _G = true,
}

local lines = {}
local function say(line) lines[#lines + 1] = line end

-- Globals, and the fields of the DSL's own global tables (pairs is the sandbox's, in sorted order).
for name, value in pairs(_G) do
  if type(name) == "string" then
    say("global " .. name)
    if type(value) == "table" and not standard_tables[name] then
      for key in pairs(value) do say("field " .. name .. "." .. tostring(key)) end
    end
  end
end

-- Modules: check_meta.py names every module file under scripts/.
for module in string.gmatch(param("modules", ""), "%S+") do
  say("module " .. module)
  local exports = require(module)
  if type(exports) == "table" then
    for key in pairs(exports) do say("export " .. module .. " " .. tostring(key)) end
  end
end

-- One small value of each type. check_meta.py fails when the interpreter's sources name a value type that
-- is not built here, so a new type is added to this list, not skipped.
local values = {
  polyline { { 0, 0 }, { 1, 0 } },                                           -- Curve
  polyline { { 0, 0, 0 }, { 1, 0, 1 } },                                     -- Curve3
  mesh { points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, triangles = { { 1, 2, 3 } } }, -- Mesh
  lsystem { axiom = "F" },                                                   -- Grammar
  volume.box { min = { 0, 0, 0 }, max = { 1, 1, 1 } },                       -- Volume
}
local probe = "__no_such_method_for_the_meta_test"
for i, value in ipairs(values) do
  local ok, message = pcall(function() return value[probe] end)
  local type_name = not ok and string.match(tostring(message), "([%w_]+) has no method '" .. probe .. "'")
  local methods = not ok and string.match(tostring(message), "; its methods: (.*)$")
  if not type_name or not methods then
    error("value " .. i .. " (" .. tostring(value) .. "): no method list in " .. tostring(message))
  end
  say("type " .. type_name)
  for method in string.gmatch(methods, "[^, ]+") do say("method " .. type_name .. " " .. method) end
end

print(table.concat(lines, "\n"))

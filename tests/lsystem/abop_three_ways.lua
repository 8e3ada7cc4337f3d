-- Issue 39: each ABOP figure's model gives the same string from lsystem{} (examples/abop/FIG.lua), from
-- lsystem.book (examples/abop/book_texts.lua) and from its .l file (examples/abop/FIG*.l, read by
-- lsystem.load). abop_three_ways.py runs this recipe in a temporary copy of examples/abop/, once per recipe
-- and variant: the recipe runs as a module with param/save stubbed and lsystem{} recording each grammar it
-- makes, in order; each is then compared with the book's text and the .l file of its sub-figure.
local figure = param("figure", "fig1_24", { doc = "the recipe of examples/abop/ (its module name)" })
local variant = param("variant", 1, { min = 1, max = 4, step = 1, doc = "the recipe's variant (1 = a)" })

local letters = { "a", "b", "c", "d", "e", "f" }
-- The sub-figure of each grammar the recipe makes, in the order it makes them.
local function subfigures(name)
  if name == "fig1_24" then return { "a", "b", "c", "d", "e", "f" } end
  if name == "fig1_31" then return { "a", "b", "c", "d", "e" } end
  if name == "fig1_27" then return { "", "", "" } end -- one grammar, three seeds
  if name == "fig2_6" or name == "fig2_7" or name == "fig2_8" then return { letters[variant] } end
  return { "" }
end

local texts = require "book_texts"
local real = lsystem
local made = {}
lsystem = setmetatable({}, {
  __index = real,
  __call = function(_, t)
    made[#made + 1] = t
    return real(t)
  end,
})
local real_param = param
param = function(name, default) return name == "variant" and variant or default end
save = function() end

require(figure)
lsystem, param = real, real_param

local subs = subfigures(figure)
assert(#made == #subs, figure .. ": the recipe made " .. #made .. " grammars, expected " .. #subs)
for i, t in ipairs(made) do
  local key = figure .. subs[i]
  local text = assert(texts[key], key .. ": no book text in book_texts.lua")
  local n = assert(tonumber(text:match("n = (%d+)") or text:match("derivation length: (%d+)")), key .. ": no n")
  local own = real(t)
  local book = lsystem.book(text, { seed = t.seed })
  local file = lsystem.load(key .. ".l", { seed = t.seed, angle = t.angle, tropism = t.tropism })
  local function same(a, b, level, what)
    if a == b then return end
    local at = 1
    while a:byte(at) == b:byte(at) do at = at + 1 end
    error(key .. ": level " .. level .. ": " .. what .. " differs from lsystem{}'s at byte " .. at .. " (" ..
          b:sub(at, at + 15) .. " vs " .. a:sub(at, at + 15) .. ")", 0)
  end
  local levels = { 0, 1, 2, 3, n }
  for _, level in ipairs(levels) do
    local s = own:string(level)
    same(s, book:string(level), level, "lsystem.book's string")
    same(s, file:string(level), level, key .. ".l's string")
  end
  -- The book's n and the file's derivation length are each one's default level.
  same(own:string(n), book:string(), n, "lsystem.book's string at its default level")
  same(own:string(n), file:string(), n, key .. ".l's string at its default level")
  print(key .. ": the same " .. #own:string(n) .. " bytes at level " .. n .. " three ways")
end

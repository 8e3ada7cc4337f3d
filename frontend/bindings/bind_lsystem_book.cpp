// lsystem.book(text [, options]): a grammar written in the book's notation (kernels/lsystem/book_text.h),
// made through lsystem{}'s own reader: the text's axiom, rules, #define, #ignore, derivation length and δ
// become the options axiom, rules, define, ignore, level and angle; the table gives the rest (draw, seed,
// tropism, ...).
#include <string>

#include "frontend/bindings/lsystem_value.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "kernels/base/error.h"
#include "kernels/lsystem/book_text.h"

namespace selfsim::interp {

namespace {

// Sets options[key] from the text, refusing a table that gives it as well: one of them would be ignored.
template <class Push>
void set_from_text(lua_State* L, int options, const char* key, Push&& push) {
  if (lua_getfield(L, options, key) != LUA_TNIL)
    throw Error(std::string("option '") + key + "' is given both by the text and by the table: keep one");
  lua_pop(L, 1);
  push();
  lua_setfield(L, options, key);
}

}  // namespace

// Pushes the lsystem{} options that the book grammar and the table at `table` (0: none) give together.
void push_book_options(lua_State* L, const lsystem::BookGrammar& b, int table) {
  lua_newtable(L);
  const int options = lua_gettop(L);
  if (table != 0) {
    lua_pushnil(L);
    while (lua_next(L, table) != 0) {
      lua_pushvalue(L, -2);
      lua_insert(L, -2);
      lua_rawset(L, options);
    }
  }
  if (b.axiom) set_from_text(L, options, "axiom", [&] { lua_pushstring(L, b.axiom->c_str()); });
  // The productions, and cpfg's decomposition and homomorphism (interpretation) sections where it has them.
  // (A plain variable, not a structured binding: clang 14, which builds the fuzz targets, cannot capture one.)
  for (const auto& entry :
       {std::pair{lsystem::RuleSet::productions, "rules"}, std::pair{lsystem::RuleSet::decomposition, "decomposition"},
        std::pair{lsystem::RuleSet::interpretation, "interpretation"}}) {
    const lsystem::RuleSet set = entry.first;
    const char* const key = entry.second;
    bool any = set == lsystem::RuleSet::productions;
    for (const lsystem::BookRule& r : b.rules) any = any || r.set == set;
    if (!any) continue;
    set_from_text(L, options, key, [&] {
      lua_newtable(L);
      lua_Integer n = 0;
      for (const lsystem::BookRule& r : b.rules)
        if (r.set == set) {
          lua_pushstring(L, r.text.c_str());
          lua_rawseti(L, -2, ++n);
        }
    });
  }
  if (b.max_depth) set_from_text(L, options, "max_depth", [&] { lua_pushinteger(L, *b.max_depth); });
  if (!b.defines.empty())
    set_from_text(L, options, "define", [&] {
      lua_newtable(L);
      for (const auto& [name, value] : b.defines) {
        lua_pushnumber(L, value);
        lua_setfield(L, -2, name.c_str());
      }
    });
  // The book's contexts skip only what #ignore lists (cpfg's too): without it, nothing.
  set_from_text(L, options, "ignore", [&] { lua_pushstring(L, b.ignore.value_or("").c_str()); });
  if (b.angle) set_from_text(L, options, "angle", [&] { lua_pushnumber(L, *b.angle); });
  if (b.level) set_from_text(L, options, "level", [&] { lua_pushinteger(L, *b.level); });
}

int lsystem_book(lua_State* L) {
  return call_kernel(L, "lsystem.book", [&] {
    const int top = lua_gettop(L);
    if (top < 1 || lua_type(L, 1) != LUA_TSTRING)
      throw Error("argument 1 must be the book's text, lsystem.book[[ ... ]], got " + describe(L, 1));
    if (top > 2) throw Error("takes the book's text and a table of options, lsystem.book(text, { angle = 25.7 })");
    if (top == 2 && lua_type(L, 2) != LUA_TTABLE && lua_type(L, 2) != LUA_TNIL)
      throw Error("argument 2 must be a table of options, got " + describe(L, 2));
    lsystem::BookGrammar b;
    try {
      b = lsystem::read_book(text_value(L, 1, "argument 1 (the book's text)"));
    } catch (const lsystem::BookError& e) {
      throw Error("line " + std::to_string(e.line) + " of the text: " + e.what());
    }
    if (!b.axiom && !(top == 2 && lua_type(L, 2) == LUA_TTABLE && lua_getfield(L, 2, "axiom") != LUA_TNIL))
      throw Error("the text has no axiom: write it as the book does, ω : F (or give option 'axiom')");
    push_book_options(L, b, top == 2 && lua_type(L, 2) == LUA_TTABLE ? 2 : 0);
    return push_lsystem(L, lua_gettop(L));
  });
}

}  // namespace selfsim::interp

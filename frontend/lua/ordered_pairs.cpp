// pairs() for recipes in a fixed order. Lua seeds its string hashes per process, so the order of pairs()
// over string keys changes from run to run; recipes that build outputs in a pairs() loop would then write
// different bytes for the same recipe and seed. The keys are visited as push_sorted_keys orders them.
#include "frontend/lua/lua_support.h"
#include "frontend/lua/sandbox.h"

namespace selfsim::interp {

namespace {

// The iterator: upvalue 1 the sorted keys, upvalue 2 how many have been visited. Keys removed during the
// loop (assigned nil) are skipped, as next() would.
int ordered_next(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);  // the iterator may be called by hand, with anything
  lua_Integer i = lua_tointeger(L, lua_upvalueindex(2));
  const auto n = static_cast<lua_Integer>(lua_rawlen(L, lua_upvalueindex(1)));
  while (++i <= n) {
    lua_rawgeti(L, lua_upvalueindex(1), i);
    lua_pushvalue(L, -1);
    if (lua_rawget(L, 1) != LUA_TNIL) {
      lua_pushinteger(L, i);
      lua_replace(L, lua_upvalueindex(2));
      return 2;
    }
    lua_pop(L, 2);
  }
  lua_pushinteger(L, n);
  lua_replace(L, lua_upvalueindex(2));
  lua_pushnil(L);
  return 1;
}

int ordered_pairs(lua_State* L) {
  luaL_checkany(L, 1);
  if (luaL_getmetafield(L, 1, "__pairs") != LUA_TNIL) {  // the table's own iteration, as Lua's pairs()
    lua_pushvalue(L, 1);
    lua_call(L, 1, 3);
    return 3;
  }
  luaL_checktype(L, 1, LUA_TTABLE);
  return call_kernel(L, "pairs", [&] {
    push_sorted_keys(L, 1);
    lua_pushinteger(L, 0);
    lua_pushcclosure(L, ordered_next, 2);
    lua_pushvalue(L, 1);
    lua_pushnil(L);
    return 3;
  });
}

}  // namespace

void install_ordered_pairs(lua_State* L) { lua_register(L, "pairs", ordered_pairs); }

}  // namespace selfsim::interp

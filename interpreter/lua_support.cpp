#include "interpreter/lua_support.h"

#include <cmath>
#include <cstdio>

#include "interpreter/run_context.h"

namespace selfsim::interp {

std::string recipe_where(lua_State* L) {
  const std::string library = "@" + RunContext::of(L).scripts_dir.string();
  std::string first;
  lua_Debug ar;
  for (int level = 1; lua_getstack(L, level, &ar); ++level) {
    lua_getinfo(L, "Sl", &ar);
    if (ar.currentline <= 0) continue;
    const std::string where = std::string(ar.short_src) + ":" + std::to_string(ar.currentline) + ": ";
    if (first.empty()) first = where;
    if (std::string_view(ar.source).substr(0, library.size()) != library) return where;
  }
  return first;
}

std::string describe(lua_State* L, int index) {
  switch (lua_type(L, index)) {
    case LUA_TNUMBER: {
      if (lua_isinteger(L, index)) return std::to_string(lua_tointeger(L, index));
      const double v = lua_tonumber(L, index);
      if (std::isnan(v)) return "NaN";  // not "-nan", whatever the sign bit of 0/0
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.14g", v);
      return buf;
    }
    case LUA_TSTRING: return "'" + std::string(lua_tostring(L, index)) + "'";
    case LUA_TNIL: return "nil";
    case LUA_TNONE: return "nothing";
    case LUA_TBOOLEAN: return lua_toboolean(L, index) ? "true" : "false";
    default: {
      const char* name = luaL_typename(L, index);
      if (luaL_getmetafield(L, index, "__name") == LUA_TSTRING) {
        std::string n = lua_tostring(L, -1);
        lua_pop(L, 1);
        return "a " + n.substr(n.find('.') + 1);
      }
      return std::string("a ") + name;
    }
  }
}

void push_error(lua_State* L, const char* fn, const std::string& message) {
  const std::string where = recipe_where(L);
  lua_pushfstring(L, "%s%s: %s", where.c_str(), fn, message.c_str());
}

std::string cancel_message(lua_State* L) {
  const std::string reason = RunContext::of(L).stop_reason();
  return reason.empty() ? "cancelled" : reason;
}

}  // namespace selfsim::interp

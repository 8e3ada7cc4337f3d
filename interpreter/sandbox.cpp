#include "interpreter/sandbox.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "interpreter/lua_support.h"

namespace selfsim::interp {

namespace {

const char* const loaded_key = "selfsim.loaded";

// Stops the script between instructions once the run is cancelled; the message carries the line it was on.
void stop_hook(lua_State* L, lua_Debug* ar) {
  {
    const std::string reason = RunContext::of(L).stop_reason();
    if (reason.empty()) return;
    lua_getinfo(L, "Sl", ar);
    lua_pushfstring(L, "%s:%d: %s", ar->short_src, ar->currentline, reason.c_str());
  }  // reason freed before the longjmp
  lua_error(L);
}

bool valid_module_name(const std::string& name) {
  if (name.empty() || name.front() == '.' || name.back() == '.') return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.')) return false;
  return name.find("..") == std::string::npos;
}

// Loads module `name` (scripts/ first, then the recipe's folder; text chunks only) and leaves its value on
// the stack, or leaves an error message and returns false. Runs the module with lua_pcall so that its
// errors never longjmp past this function's C++ objects.
bool load_module(lua_State* L, const char* module) {
  const std::string name = module;
  if (!valid_module_name(name)) {
    lua_pushfstring(L, "%srequire: invalid module name '%s'", recipe_where(L).c_str(), module);
    return false;
  }
  lua_getfield(L, LUA_REGISTRYINDEX, loaded_key);
  if (lua_getfield(L, -1, module) != LUA_TNIL) return true;
  lua_pop(L, 1);
  RunContext& run = RunContext::of(L);
  std::string rel = name;
  std::replace(rel.begin(), rel.end(), '.', '/');
  rel += ".lua";
  for (const auto& dir : {run.scripts_dir, run.config.recipe.parent_path()}) {
    const std::filesystem::path file = dir / rel;
    if (!std::filesystem::is_regular_file(file)) continue;
    if (luaL_loadfilex(L, file.c_str(), "t") != LUA_OK) return false;
    lua_pushstring(L, module);
    if (lua_pcall(L, 1, 1, 0) != LUA_OK) return false;
    if (lua_isnil(L, -1)) {
      lua_pop(L, 1);
      lua_pushboolean(L, 1);
    }
    lua_pushvalue(L, -1);
    lua_setfield(L, -3, module);  // cache it
    return true;
  }
  lua_pushfstring(L, "%srequire: module '%s' not found in scripts/ or the recipe's folder", recipe_where(L).c_str(), module);
  return false;
}

int sandbox_require(lua_State* L) {
  if (!load_module(L, luaL_checkstring(L, 1))) return lua_error(L);
  return 1;
}

// __index of the guarded os and io tables: a clear message instead of "attempt to call a nil value".
int unavailable(lua_State* L) {
  lua_getmetatable(L, 1);
  lua_getfield(L, -1, "library");
  return luaL_error(L, "%s.%s is not available in recipes: they cannot run programs or touch files (write outputs with save)",
                    lua_tostring(L, -1), luaL_optstring(L, 2, "?"));
}

// Pushes an empty table whose missing fields raise `unavailable`.
void push_guarded_table(lua_State* L, const char* library) {
  lua_newtable(L);
  lua_newtable(L);
  lua_pushstring(L, library);
  lua_setfield(L, -2, "library");
  lua_pushcfunction(L, unavailable);
  lua_setfield(L, -2, "__index");
  lua_setmetatable(L, -2);
}

// os keeps only its clock and date functions; io is all guard.
void open_safe_os_and_io(lua_State* L) {
  luaL_requiref(L, "os", luaopen_os, 0);
  push_guarded_table(L, "os");
  for (const char* keep : {"clock", "time", "date", "difftime"}) {
    lua_getfield(L, -2, keep);
    lua_setfield(L, -2, keep);
  }
  lua_setglobal(L, "os");
  lua_pop(L, 1);
  push_guarded_table(L, "io");
  lua_setglobal(L, "io");
}

}  // namespace

lua_State* new_sandbox(RunContext& run) {
  lua_State* L = luaL_newstate();
  if (L == nullptr) return nullptr;
  const luaL_Reg libs[] = {{LUA_GNAME, luaopen_base},        {LUA_TABLIBNAME, luaopen_table}, {LUA_STRLIBNAME, luaopen_string},
                           {LUA_MATHLIBNAME, luaopen_math},  {LUA_UTF8LIBNAME, luaopen_utf8}, {LUA_COLIBNAME, luaopen_coroutine}};
  for (const auto& lib : libs) {
    luaL_requiref(L, lib.name, lib.func, 1);
    lua_pop(L, 1);
  }
  open_safe_os_and_io(L);
  for (const char* unsafe : {"dofile", "loadfile", "load"}) {
    lua_pushnil(L);
    lua_setglobal(L, unsafe);
  }
  lua_newtable(L);
  lua_setfield(L, LUA_REGISTRYINDEX, loaded_key);
  lua_register(L, "require", sandbox_require);

  // Same recipe, same seed, same files: math.random is seeded from --seed, never from the clock.
  lua_getglobal(L, "math");
  lua_getfield(L, -1, "randomseed");
  lua_pushinteger(L, run.config.seed);
  lua_call(L, 1, 0);
  lua_pop(L, 1);

  run.install(L);
  lua_sethook(L, stop_hook, LUA_MASKCOUNT, 10000);
  return L;
}

}  // namespace selfsim::interp

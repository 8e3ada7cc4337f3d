#include "frontend/lua/sandbox.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "frontend/lua/folder_check.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"

namespace selfsim::interp {

namespace {

const char* const loaded_key = "selfsim.loaded";

bool valid_module_name(const std::string& name) {
  if (name.empty() || name.front() == '.' || name.back() == '.') return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.')) return false;
  return name.find("..") == std::string::npos;
}

// The module most likely meant by `name`, which neither folder holds: modules beside it in either folder
// ("selfsim.curve" for "selfsim.curves"), or of the DSL's library ("curves" for "selfsim.curves"); the
// recipe itself is not one. Empty when none is close.
std::string module_meant(const RunContext& run, const std::string& name) {
  const std::size_t dot = name.rfind('.');
  const std::string prefix = dot == std::string::npos ? "" : name.substr(0, dot + 1);
  std::string sub = prefix;
  std::replace(sub.begin(), sub.end(), '.', '/');
  std::vector<std::string> modules;
  auto add = [&](const std::filesystem::path& folder, const std::string& module_prefix) {
    for (const std::string& file : files_in(folder, {".lua"})) {
      const std::string module = module_prefix + std::filesystem::path(file).stem().string();
      if (valid_module_name(module) && std::find(modules.begin(), modules.end(), module) == modules.end())
        modules.push_back(module);
    }
  };
  const std::filesystem::path recipe_dir = run.config.recipe.parent_path();
  add(run.scripts_dir / sub, prefix);
  add(run.scripts_dir / "selfsim", "selfsim.");
  add(recipe_dir / sub, prefix);
  if (prefix.empty()) std::erase(modules, run.config.recipe.stem().string());
  std::string near = suggestion(name, modules);
  if (!near.empty()) return near;
  // The last part alone: "curves" for "selfsim.curves".
  auto last = [](const std::string& m) { return m.substr(m.rfind('.') + 1); };
  std::vector<std::string> lasts;
  for (const std::string& m : modules) lasts.push_back(last(m));
  near = suggestion(last(name), lasts);
  for (const std::string& m : modules)
    if (!near.empty() && last(m) == near) return m;
  return "";
}

// Loads module `name` (scripts/ first, then the recipe's folder; text chunks only) and leaves its value on
// the stack, or leaves an error message and returns false. Runs the module with lua_pcall so that its
// errors never longjmp past this function's C++ objects.
int loading_marker;  // its address marks a module being loaded, in the cache of loaded modules

bool load_module(lua_State* L, const std::string& name) {
  const char* module = name.c_str();
  if (!valid_module_name(name)) {
    lua_pushfstring(L, "%srequire: invalid module name '%s' (letters, digits, '_' and '.')", recipe_where(L).c_str(),
                    shown_text(name).c_str());
    return false;
  }
  lua_getfield(L, LUA_REGISTRYINDEX, loaded_key);
  const int cached = lua_getfield(L, -1, module);
  if (cached == LUA_TLIGHTUSERDATA) {  // the marker set below: the module is still loading
    lua_pushfstring(L, "%srequire: module '%s' requires itself while loading (a require cycle)",
                    recipe_where(L).c_str(), module);
    return false;
  }
  if (cached != LUA_TNIL) return true;
  lua_pop(L, 1);
  RunContext& run = RunContext::of(L);
  std::string rel = name;
  std::replace(rel.begin(), rel.end(), '.', '/');
  rel += ".lua";
  for (const auto& dir : {run.scripts_dir, run.config.recipe.parent_path()}) {
    const std::filesystem::path file = dir / rel;
    std::error_code ec;  // never throw through Lua: a name too long is just "not found"
    if (!std::filesystem::is_regular_file(file, ec)) continue;
    // Modules come from inside their folder: a symbolic link leading out of it is refused, as save does.
    if (!resolves_inside(dir, file)) {
      lua_pushfstring(L, "%srequire: module '%s' (%s) leads outside its folder through a symbolic link",
                      recipe_where(L).c_str(), module, file.c_str());
      return false;
    }
    if (load_lua_file(L, file, "module") != LUA_OK) {
      // Syntax errors name the module's file and line already; others (a binary chunk) name nothing.
      const std::string chunk = file.string() + ":";
      const char* message = lua_tostring(L, -1);
      if (message == nullptr || std::string_view(message).substr(0, chunk.size()) != chunk)
        lua_pushfstring(L, "%srequire: cannot load module '%s' (%s): %s", recipe_where(L).c_str(), module, file.c_str(),
                        message ? message : "not text");
      return false;
    }
    lua_pushlightuserdata(L, &loading_marker);
    lua_setfield(L, -3, module);
    lua_pushstring(L, module);
    const int status = lua_pcall(L, 1, 1, 0);
    lua_pushnil(L);
    lua_setfield(L, -3, module);  // no longer loading
    if (status != LUA_OK) return false;
    if (lua_isnil(L, -1)) {
      lua_pop(L, 1);
      lua_pushboolean(L, 1);
    }
    lua_pushvalue(L, -1);
    lua_setfield(L, -3, module);  // cache it
    return true;
  }
  // Where it looked, in words that hold on any machine, and the likeliest module meant.
  std::string near;
  try {
    near = module_meant(run, name);
  } catch (const std::exception&) {  // out of memory: no suggestion
  }
  const std::string message = recipe_where(L) + "require: module '" + shown_text(name) + "' not found: looked for " +
                              shown_text(rel) + " in the DSL's scripts/ folder and in the recipe's folder" +
                              (near.empty() ? "" : " (did you mean '" + near + "'?)");
  lua_pushlstring(L, message.data(), message.size());
  return false;
}

int sandbox_require(lua_State* L) {
  bool loaded = false;
  {
    std::string message;
    std::size_t n = 0;
    const char* name = lua_type(L, 1) == LUA_TSTRING ? lua_tolstring(L, 1, &n) : nullptr;
    if (name == nullptr)
      message = "module name must be a string, got " + describe(L, 1);
    else if (std::string_view(name, n).find('\0') != std::string_view::npos)
      message = "module name must not contain NUL bytes, got '" + shown_text(std::string_view(name, n)) + "'";
    else
      loaded = load_module(L, std::string(name, n));
    if (!message.empty()) push_error(L, "require", message);
  }  // strings freed before the error unwinds
  if (!loaded) return lua_error(L);
  return 1;
}

// __index of the guarded os and io tables: a clear message instead of "attempt to call a nil value".
int unavailable(lua_State* L) {
  lua_getmetatable(L, 1);
  lua_getfield(L, -1, "library");
  std::size_t n = 0;
  const char* text = lua_type(L, 2) == LUA_TSTRING ? lua_tolstring(L, 2, &n) : nullptr;
  lua_pushstring(L, text ? shown_text(std::string_view(text, n)).c_str() : "?");
  return luaL_error(
      L, "%s.%s is not available in recipes: they cannot run programs or touch files (write outputs with save)",
      lua_tostring(L, -2), lua_tostring(L, -1));
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

// math.randomseed(...) with upvalues (the original, --seed): with no argument, the run's seed.
int seeded_randomseed(lua_State* L) {
  if (lua_gettop(L) == 0) lua_pushvalue(L, lua_upvalueindex(2));
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
  return lua_gettop(L);
}

// Errors outside any protected call would abort the process; selfsim runs everything under lua_pcall, so
// this is a last resort that still ends with one line and no partial file.
int panic(lua_State* L) {
  const char* message = lua_tostring(L, -1);
  std::fprintf(stderr, "selfsim: unprotected Lua error: %s\n", message ? shown_text(message, 500).c_str() : "?");
  std::fflush(stderr);
  std::_Exit(1);
}

// warn() and errors in finalizers, one line each: "selfsim: warning: ...". "@on"/"@off" are ignored. A
// finalizer that failed may have left a value unreleased: the next budget check sweeps them. Finalizers
// fail by the thousand at the C-stack limit, where every call fails; the run's own error says so once, and
// those warnings are dropped.
void warning(void* ud, const char* message, int to_continue) {
  auto& run = *static_cast<RunContext*>(ud);
  std::string& pending = run.pending_warning;
  if (pending.empty() && !to_continue && message[0] == '@') return;
  pending += message;
  if (to_continue && pending.size() < 4096) return;
  const bool finalizer = pending.rfind("error in __gc", 0) == 0;
  if (finalizer) run.values.sweep_due = true;
  if (!(finalizer && pending.find("C stack overflow") != std::string::npos))
    std::fprintf(stderr, "selfsim: warning: %s\n", shown_text(pending, 500).c_str());
  pending.clear();
}

}  // namespace

lua_State* new_sandbox(RunContext& run) {
  run.memory.limit = run.config.max_memory > 0 ? run.config.max_memory : default_max_memory();
  run.memory.library = "@" + run.scripts_dir.string();
  lua_State* L = lua_newstate(limited_alloc, &run.memory);
  if (L == nullptr) return nullptr;
  run.memory.L = L;
  lua_atpanic(L, panic);
  lua_setwarnf(L, warning, &run);
  const luaL_Reg libs[] = {{LUA_GNAME, luaopen_base},        {LUA_TABLIBNAME, luaopen_table},
                           {LUA_STRLIBNAME, luaopen_string}, {LUA_MATHLIBNAME, luaopen_math},
                           {LUA_UTF8LIBNAME, luaopen_utf8},  {LUA_COLIBNAME, luaopen_coroutine}};
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

  // Same recipe, same seed, same files: math.random is seeded from --seed, never from the clock, and
  // math.randomseed() without a seed reseeds from --seed too.
  lua_getglobal(L, "math");
  lua_getfield(L, -1, "randomseed");
  lua_pushinteger(L, run.config.seed);
  lua_pushcclosure(L, seeded_randomseed, 2);
  lua_pushvalue(L, -1);
  lua_call(L, 0, 0);
  lua_setfield(L, -2, "randomseed");
  lua_pop(L, 1);
  // The string metatable is shared with the DSL's own scripts: locked like the values' metatables.
  lua_pushliteral(L, "");
  lua_getmetatable(L, -1);
  lua_pushliteral(L, "locked");
  lua_setfield(L, -2, "__metatable");
  lua_pop(L, 2);

  run.install(L);
  install_ordered_pairs(L);
  install_stop_guards(L);
  return L;
}

}  // namespace selfsim::interp

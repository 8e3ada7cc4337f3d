// How a recipe is stopped (--timeout, Ctrl-C, SIGTERM) from inside Lua: a count hook raises the stop
// between instructions, and the functions that catch errors (pcall, xpcall, coroutine.resume and
// coroutine.close) raise it again once they return, so `while true do pcall(f) end` cannot swallow it.
// What no hook can reach (finalizers run with hooks off, long C calls like string.rep) is the watchdog's.
#include "frontend/lua/lua_support.h"
#include "frontend/lua/run_context.h"
#include "frontend/lua/sandbox.h"

namespace selfsim::interp {

namespace {

// Raises the stop, naming the recipe line, if the run is being stopped.
void raise_if_stopped(lua_State* L) {
  {
    const std::string reason = RunContext::of(L).stop_reason();
    if (reason.empty()) return;
    lua_pushfstring(L, "%s%s", recipe_where(L).c_str(), reason.c_str());
  }  // reason freed before the error unwinds
  lua_error(L);
}

void stop_hook(lua_State* L, lua_Debug*) { raise_if_stopped(L); }

int after_protected_call(lua_State* L, int, lua_KContext) {
  raise_if_stopped(L);
  return lua_gettop(L);
}

// Calls the wrapped function (upvalue 1) with every argument and returns what it returns, unless the run
// is being stopped. A continuation keeps yields across it working (pcall(coroutine.yield) in a coroutine).
int protected_call(lua_State* L) {
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_callk(L, lua_gettop(L) - 1, LUA_MULTRET, 0, after_protected_call);
  return after_protected_call(L, LUA_OK, 0);
}

// Replaces table[name] (the table on top of the stack) by protected_call around it.
void guard_field(lua_State* L, const char* name) {
  lua_getfield(L, -1, name);
  lua_pushcclosure(L, protected_call, 1);
  lua_setfield(L, -2, name);
}

}  // namespace

void install_stop_guards(lua_State* L) {
  lua_pushglobaltable(L);
  guard_field(L, "pcall");
  guard_field(L, "xpcall");
  lua_pop(L, 1);
  lua_getglobal(L, "coroutine");
  guard_field(L, "resume");
  guard_field(L, "close");
  lua_pop(L, 1);
  // Coroutines inherit the hook from the thread that creates them.
  lua_sethook(L, stop_hook, LUA_MASKCOUNT, 10000);
}

}  // namespace selfsim::interp

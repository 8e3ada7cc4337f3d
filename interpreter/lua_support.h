// What every binding needs from Lua: turning kernel exceptions into Lua errors at the recipe line that
// called the kernel, and userdata values with a metatable per type. Only interpreter/ includes Lua.
#pragma once

#include <lua.hpp>

#include <new>
#include <string>
#include <utility>

#include "kernels/geom/error.h"

namespace selfsim::interp {

// "recipe.lua:12: " for the innermost frame that is not one of the DSL's own scripts/ files.
std::string recipe_where(lua_State* L);

// Describes a Lua value for an error message: 41, 'abc', a table, nil.
std::string describe(lua_State* L, int index);

// Pushes "where: fn: message", the error for the recipe line that called fn. Raise it with lua_error once
// no C++ object with a destructor is alive in the frame: lua_error longjmps past destructors.
void push_error(lua_State* L, const char* fn, const std::string& message);

// Message for a cancelled kernel: the timeout or the interrupt that caused it.
std::string cancel_message(lua_State* L);

// Runs body (which returns the number of Lua results) and turns any C++ exception into a Lua error raised
// after the catch block, never inside it: lua_error longjmps, which must not cross live C++ handlers.
// Readers may throw with values still pushed: Lua discards a C function's stack slots when it raises.
template <class Body>
int call_kernel(lua_State* L, const char* fn, Body&& body) {
  {
    std::string message;
    try {
      return std::forward<Body>(body)();
    } catch (const Cancelled&) {
      message = cancel_message(L);
    } catch (const Error& e) {
      message = e.what();
    } catch (const std::bad_alloc&) {
      message = "out of memory (lower the level, or the size of the request)";
    } catch (const std::exception& e) {
      message = std::string("internal error: ") + e.what();
    }
    push_error(L, fn, message);
  }  // message freed before the longjmp
  return lua_error(L);
}

// A C++ value living in a Lua userdata whose metatable is registered under `type` (its __name).
template <class T>
T& push_value(lua_State* L, const char* type, T&& value) {
  void* block = lua_newuserdatauv(L, sizeof(T), 0);
  T* v = new (block) T(std::forward<T>(value));
  luaL_setmetatable(L, type);
  return *v;
}

// The value at index if it is a userdata of `type`, else nullptr.
template <class T>
T* test_value(lua_State* L, int index, const char* type) {
  return static_cast<T*>(luaL_testudata(L, index, type));
}

// The method's receiver (argument 1) as a T, or a recipe error that points at the usual slip, a '.'
// written for ':'.
template <class T>
T& check_self(lua_State* L, const char* type, const char* method) {
  if (T* v = test_value<T>(L, 1, type)) return *v;
  {
    const std::string name = std::string(type).substr(std::string(type).find('.') + 1);
    push_error(L, method, "expected a " + name + " before ':' (write value:" + method + "(...)), got " + describe(L, 1));
  }
  lua_error(L);
  std::abort();  // not reached: lua_error does not return
}

// Registers a metatable for T: __name, __gc (runs ~T), __index = the given methods.
template <class T>
void register_type(lua_State* L, const char* type, const luaL_Reg* methods, lua_CFunction tostring) {
  luaL_newmetatable(L, type);
  lua_pushcfunction(L, [](lua_State* S) {
    static_cast<T*>(lua_touserdata(S, 1))->~T();
    return 0;
  });
  lua_setfield(L, -2, "__gc");
  lua_pushcfunction(L, tostring);
  lua_setfield(L, -2, "__tostring");
  lua_newtable(L);
  luaL_setfuncs(L, methods, 0);
  lua_setfield(L, -2, "__index");
  lua_pop(L, 1);
}

}  // namespace selfsim::interp

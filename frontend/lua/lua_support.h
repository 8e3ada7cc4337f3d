// What every binding needs from Lua: turning kernel exceptions into Lua errors at the recipe line that
// called the kernel, and userdata values with a metatable per type. Only frontend/ includes Lua.
#pragma once

#include <cstdint>
#include <filesystem>
#include <lua.hpp>
#include <memory>
#include <new>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kernels/base/budget.h"
#include "kernels/base/error.h"

namespace selfsim::interp {

// "recipe.lua:12: " for the innermost frame that is not one of the DSL's own scripts/ files.
std::string recipe_where(lua_State* L);

// Loads the Lua text chunk in `file` as luaL_loadfilex(L, file, "t") does (a UTF-8 BOM and a first line
// starting with '#' skipped, line numbers kept), but through io::RegularFile: opened without blocking and
// only if it is a regular file, so a FIFO or a device put in the place of a recipe or module is refused at
// once instead of waited on. On failure pushes "cannot open WHAT 'FILE': REASON" and returns LUA_ERRFILE.
// `text`, where given, gets the bytes loaded (so their hash is of what ran).
int load_lua_file(lua_State* L, const std::filesystem::path& file, const char* what, std::string* text = nullptr);
// The same for chunks whose source starts with `library` ("@/path/scripts"), from stack level first_level
// (1 skips the running C function; 0 from inside the allocator, where a Lua function may be running). Only
// reads the stack, so it is safe where nothing may be pushed.
std::string stack_where(lua_State* L, const std::string& library, int first_level);

// Text from a recipe made fit for a one-line message: control characters escaped (a newline as \n) and
// anything past max_bytes cut, with the full size said.
std::string shown_text(std::string_view text, std::size_t max_bytes = 60);

// Pushes a list of the keys of the table at `table` in a fixed order (numbers, strings, booleans, then any
// other key in traversal order) and returns their count. Lua's own order depends on a per-process hash
// seed; recipes and messages must not.
int push_sorted_keys(lua_State* L, int table);

// The length of the list (a table with entries 1 to n and no other key) at index. Throws Error naming the
// first key that is not an entry, or the first hole: `what` names the table, `hint` is added to the message
// for a stray key.
lua_Integer list_length(lua_State* L, int index, const std::string& what, const std::string& hint = "");

// Describes a Lua value for an error message: 41, 'abc', a table, nil.
std::string describe(lua_State* L, int index);

// Pushes "where: fn: message", the error for the recipe line that called fn. Raise it with lua_error once
// no C++ object with a destructor is alive in the frame: lua_error longjmps past destructors.
void push_error(lua_State* L, const char* fn, const std::string& message);

// Records `detail` (lines shown under the message) for the error value on top of the stack.
void note_error_detail(lua_State* L, const std::string& detail);
// The detail recorded for the error value at index, or "" (another error, or none recorded).
std::string error_detail(lua_State* L, int index);

// True once the recipe has returned or failed.
bool run_has_ended(lua_State* L);

// Message for a cancelled kernel: the timeout or the interrupt that caused it.
std::string cancel_message(lua_State* L);
// The message of a kernel stopped under `selfsim params`, which runs a recipe only up to its first heavy step.
inline constexpr const char* params_stop = "stopped here: params lists those read before the first heavy step";

// Ends the progress bar a kernel may have drawn (every call_kernel does, whatever happened).
void end_progress(lua_State* L) noexcept;

// Runs body (which returns the number of Lua results) and turns any C++ exception into a Lua error raised
// after the catch block, never inside it: lua_error longjmps, which must not cross live C++ handlers.
// Readers may throw with values still pushed: Lua discards a C function's stack slots when it raises.
template <class Body>
int call_kernel(lua_State* L, const char* fn, Body&& body) {
  {
    std::string message, detail;
    try {
      // Finalizers may run after the recipe has returned or failed (while the state closes, Lua no longer
      // finalizes new values): nothing is made or written then.
      if (run_has_ended(L))
        throw Error("the recipe has ended: nothing more is made or written (called from a finalizer?)");
      const int results = std::forward<Body>(body)();
      end_progress(L);
      return results;
    } catch (const Cancelled&) {
      message = cancel_message(L);
    } catch (const DetailedError& e) {
      message = e.what();
      detail = e.detail;
    } catch (const Error& e) {
      message = e.what();
    } catch (const std::bad_alloc&) {
      message = "out of memory (lower the level, or the size of the request)";
    } catch (const std::exception& e) {
      message = std::string("internal error: ") + e.what();
    }
    end_progress(L);
    push_error(L, fn, message);
    if (!detail.empty()) note_error_detail(L, detail);
  }  // message freed before the longjmp
  return lua_error(L);
}

// A C++ value in a Lua userdata: the userdata holds the value's id in the run's LiveValues (live_values.h),
// which owns it, so that a userdata freed without its finalizer cannot leak it. The finalizer releases the
// id; a recipe's own finalizer that resurrects the userdata then finds a recognisably dead value.
// Values are shared: a binding holds its own reference for the whole call, so a finalizer that runs while
// the call is back in Lua (an options table's __index, a garbage collection) cannot free it under the call.
template <class T>
using Held = std::shared_ptr<const T>;

struct Box {
  std::uint64_t id;
};

// Takes ownership of a new value for the userdata about to be made (counting its bytes against
// --max-memory, which throws Error when they do not fit) and returns its id.
std::uint64_t adopt_value(lua_State* L, std::shared_ptr<const void> value, double points, std::size_t bytes);
// Records the userdata on top of the stack as the holder of value `id` and counts its points.
void hold_value(lua_State* L, std::uint64_t id);
// The value of `id`, or null once released.
std::shared_ptr<const void> live_value(lua_State* L, std::uint64_t id);
// Releases value `id` and what it counted (a finalizer; nothing when it was released already).
void release_value(lua_State* L, std::uint64_t id);
// Releases every value whose userdata has been collected without its finalizer having run.
void sweep_values(lua_State* L);

// The value's type name without the "selfsim." prefix: "Curve".
std::string type_word(const char* type);

// Adds `points` to the run's held points (negative to release them).
void hold_points(lua_State* L, double points);

// The run's point budget: --max-points and the points live values hold.
PointBudget run_budget(lua_State* L);

// Runs make(budget) with the run's point budget. When that is refused while other values hold points, some
// may be garbage the recipe has dropped: collect it and try once more.
template <class Make>
auto with_budget(lua_State* L, Make&& make) {
  try {
    return make(run_budget(L));
  } catch (const BudgetError&) {
    if (run_budget(L).held == 0) throw;
  }
  lua_gc(L, LUA_GCCOLLECT);
  sweep_values(L);  // values whose finalizers could not run
  return make(run_budget(L));
}

// Throws BudgetError unless `predicted` more points fit the run's budget, after collecting garbage the
// recipe has dropped when that makes the difference.
inline void check_run_budget(lua_State* L, double predicted, const std::string& what) {
  with_budget(L, [&](const PointBudget& b) {
    check_budget(predicted, b, what);
    return 0;
  });
}

// Counts `bytes` of C++ memory against --max-memory (negative to release them); throws Error with the
// out-of-memory message when they do not fit.
void hold_memory(lua_State* L, double bytes);

// Pushes a new userdata of metatable `type` holding value, whose `points` count against the run's point
// budget and `bytes` against its memory limit.
template <class T>
void push_value(lua_State* L, const char* type, T&& value, double points = 0, std::size_t bytes = 0) {
  const std::uint64_t id = adopt_value(L, std::make_shared<const T>(std::forward<T>(value)), points, bytes);
  new (lua_newuserdatauv(L, sizeof(Box), 0)) Box{id};
  luaL_setmetatable(L, type);
  hold_value(L, id);
}

// The value at index if it is a userdata of `type`, else null. Throws Error for a value of that type whose
// finalizer has run ("Curve used after it was freed"). Keep the result for as long as the value is used.
template <class T>
Held<T> test_value(lua_State* L, int index, const char* type) {
  auto* box = static_cast<Box*>(luaL_testudata(L, index, type));
  if (box == nullptr) return nullptr;
  std::shared_ptr<const void> v = live_value(L, box->id);
  if (!v) throw Error(type_word(type) + " used after it was freed (kept alive by a finalizer)");
  return std::static_pointer_cast<const T>(std::move(v));
}

// The method's receiver (argument 1), or a recipe error that points at the usual slip, a '.' written for
// ':'. Keep the result for the whole call.
template <class T>
Held<T> check_self(lua_State* L, const char* type, const char* method) {
  {
    std::string message, detail;
    try {
      if (Held<T> v = test_value<T>(L, 1, type)) return v;
      message =
          "expected a " + type_word(type) + " before ':' (write value:" + method + "(...)), got " + describe(L, 1);
    } catch (const Error& e) {
      message = e.what();
    }
    push_error(L, method, message);
  }  // message freed before the longjmp
  lua_error(L);
  std::abort();  // not reached: lua_error does not return
}

// A method of a value type and what it takes after the value. More arguments are an error naming `takes`
// before the method runs (`g:curve(5, false)` would otherwise ignore its false).
struct Method {
  const char* name;
  lua_CFunction function;
  int arguments;      // the most it takes after the value
  const char* takes;  // for the message: "no arguments: c:length()"
};
// The message for a call with more arguments than `count` ("takes ..., got 2 arguments (the 2nd is false)"),
// or empty when it has no more.
std::string extra_arguments(lua_State* L, int count, const std::string& takes);
// A registered method: upvalues the function, its Method::arguments, takes and name.
int checked_method(lua_State* L);

// Registers a metatable for T: __name, __gc, __tostring, __index = the given methods, and __metatable so
// that getmetatable() gives recipes a string, never the table whose __gc runs destructors.
// A type's __index: its method, or an error naming the type, the likeliest method meant and all of them
// (Curve3:transform is "Curve3 has no method 'transform'", not "attempt to call a nil value").
// Upvalues: the methods table, the type's name.
int method_index(lua_State* L);

template <class T>
void register_type(lua_State* L, const char* type, const std::vector<Method>& methods, lua_CFunction tostring) {
  luaL_newmetatable(L, type);
  lua_pushstring(L, type);
  // Type-checked and idempotent: only a live Box of this type is emptied, once.
  lua_pushcclosure(
      L,
      [](lua_State* S) {
        if (auto* box = static_cast<Box*>(luaL_testudata(S, 1, lua_tostring(S, lua_upvalueindex(1)))))
          release_value(S, box->id);
        return 0;
      },
      1);
  lua_setfield(L, -2, "__gc");
  lua_pushcfunction(L, tostring);
  lua_setfield(L, -2, "__tostring");
  lua_newtable(L);
  for (const Method& m : methods) {
    lua_pushcfunction(L, m.function);
    lua_pushinteger(L, m.arguments);
    lua_pushstring(L, m.takes);
    lua_pushstring(L, m.name);
    lua_pushcclosure(L, checked_method, 4);
    lua_setfield(L, -2, m.name);
  }
  lua_pushstring(L, type);
  lua_pushcclosure(L, method_index, 2);
  lua_setfield(L, -2, "__index");
  lua_pushstring(L, "locked");
  lua_setfield(L, -2, "__metatable");
  lua_pop(L, 1);
}

}  // namespace selfsim::interp

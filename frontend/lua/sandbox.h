// The Lua state a recipe runs in: safe libraries only (no io, no os.execute, no loadlib or bytecode),
// require limited to the DSL's scripts/ and the recipe's own folder, an allocator limited by --max-memory,
// pairs() in a fixed order, and a count hook that stops runaway scripts on --timeout or Ctrl-C, as lua.c's
// lstop does (stop_guards.cpp).
#pragma once

#include <lua.hpp>

#include "frontend/lua/run_context.h"

namespace selfsim::interp {

// A new state with the sandboxed standard library and the run context installed. Caller closes it.
lua_State* new_sandbox(RunContext& run);

// stop_guards.cpp: the stop hook, and pcall, xpcall, coroutine.resume/close that cannot swallow a stop.
void install_stop_guards(lua_State* L);
// ordered_pairs.cpp: pairs() visiting keys in a fixed order.
void install_ordered_pairs(lua_State* L);

}  // namespace selfsim::interp

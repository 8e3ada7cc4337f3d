// The Lua state a recipe runs in: safe libraries only (no io, no os.execute, no loadlib or bytecode),
// require limited to the DSL's scripts/ and the recipe's own folder, and a count hook that stops
// runaway scripts on --timeout or Ctrl-C, as lua.c's lstop does.
#pragma once

#include <lua.hpp>

#include "interpreter/run_context.h"

namespace selfsim::interp {

// A new state with the sandboxed standard library and the run context installed. Caller closes it.
lua_State* new_sandbox(RunContext& run);

}  // namespace selfsim::interp

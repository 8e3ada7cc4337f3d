// Lua's allocator with a limit (--max-memory): a recipe cannot hold more than that in strings and tables.
// A refused allocation becomes Lua's memory error; the allocator notes where in the recipe it happened, since
// Lua calls no message handler for memory errors.
#pragma once

#include <cstddef>
#include <lua.hpp>
#include <string>

namespace selfsim::interp {

struct LuaMemory {
  double limit = 0;         // bytes
  std::size_t used = 0;     // bytes held by the Lua state now
  lua_State* L = nullptr;   // set once the state exists, to read the recipe line of a refusal
  std::string library;      // "@<scripts dir>": frames skipped when naming the recipe line
  std::string where;        // "recipe.lua:12: " of the last refusal
  std::size_t refused = 0;  // bytes of the last refused request
  bool over_limit = false;  // the last refusal was the limit's (else the system's)
};

// The lua_Alloc for a state whose ud is a LuaMemory.
void* limited_alloc(void* ud, void* ptr, std::size_t osize, std::size_t nsize) noexcept;

// Counts `bytes` of the recipe's C++ data (a grammar's rules) against the same limit, or releases them when
// negative. Returns false, counting nothing, when they do not fit.
bool hold_external(LuaMemory& m, double bytes);

// "out of memory: ..." for the last refusal, naming the flag that raises the limit; memory_message puts
// the recipe line of the refusal in front.
std::string memory_reason(const LuaMemory& m);
std::string memory_message(const LuaMemory& m);

}  // namespace selfsim::interp

#include "interpreter/lua_memory.h"

#include <cstdio>
#include <cstdlib>

#include "interpreter/lua_support.h"

namespace selfsim::interp {

namespace {

std::string gib(double bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g GiB", bytes / (1 << 30));
  return buf;
}

void note_refusal(LuaMemory& m, std::size_t bytes, bool over_limit) {
  m.refused = bytes;
  m.over_limit = over_limit;
  try {
    // Keep the last recipe line known: a refusal outside the recipe (while reporting) has no line of its own.
    std::string where = m.L ? stack_where(m.L, m.library, 0) : std::string();
    if (!where.empty()) m.where = std::move(where);
  } catch (...) {
  }
}

}  // namespace

void* limited_alloc(void* ud, void* ptr, std::size_t osize, std::size_t nsize) noexcept {
  auto& m = *static_cast<LuaMemory*>(ud);
  const std::size_t old = ptr ? osize : 0;  // for a new block, osize is a type tag, not a size
  if (nsize == 0) {
    std::free(ptr);
    m.used -= old;
    return nullptr;
  }
  if (nsize > old && static_cast<double>(m.used - old + nsize) > m.limit) {
    note_refusal(m, nsize, true);
    return nullptr;
  }
  void* block = std::realloc(ptr, nsize);
  if (block == nullptr) {
    if (nsize <= old) return ptr;  // Lua counts on shrinking never failing: keep the bigger block
    note_refusal(m, nsize, false);
    return nullptr;
  }
  m.used = m.used - old + nsize;
  return block;
}

std::string memory_message(const LuaMemory& m) {
  if (m.over_limit)
    return m.where + "out of memory: the recipe's Lua strings and tables would need more than --max-memory of " + gib(m.limit) +
           " (raise it with --max-memory)";
  return m.where + "out of memory: the system refused " + gib(static_cast<double>(m.refused)) + " for the recipe's Lua values";
}

}  // namespace selfsim::interp

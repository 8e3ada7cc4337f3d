#include "frontend/lua/lua_memory.h"

#include <cstdio>
#include <cstdlib>

#include "frontend/lua/lua_support.h"

namespace selfsim::interp {

namespace {

std::string gib(double bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g GiB", bytes / (1 << 30));
  return buf;
}

bool fits(const LuaMemory& m, double more) { return static_cast<double>(m.used) + more <= m.limit; }

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
  if (nsize > old && !fits(m, static_cast<double>(nsize - old))) {
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

bool hold_external(LuaMemory& m, double bytes) {
  if (bytes > 0 && !fits(m, bytes)) {
    note_refusal(m, static_cast<std::size_t>(bytes), true);
    return false;
  }
  m.used = static_cast<std::size_t>(static_cast<double>(m.used) + bytes);
  return true;
}

std::string memory_reason(const LuaMemory& m) {
  if (m.over_limit)
    return "out of memory: the recipe's Lua strings and tables would need more than --max-memory of " + gib(m.limit) +
           " (raise it with --max-memory)";
  return "out of memory: the system refused " + gib(static_cast<double>(m.refused)) + " for the recipe's Lua values";
}

std::string memory_message(const LuaMemory& m) { return m.where + memory_reason(m); }

}  // namespace selfsim::interp

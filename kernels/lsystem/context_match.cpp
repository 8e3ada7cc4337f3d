#include "kernels/lsystem/context_match.h"

#include <algorithm>

namespace selfsim::lsystem {

namespace {

// Binds module j of s to pattern m: the same symbol and number of parameters.
bool binds(const Pattern& m, const ModuleString& s, std::size_t j, double* params) {
  if (s.symbols[j] != m.symbol) return false;
  const std::span<const double> a = s.args_of(j);
  if (a.size() != m.params.size()) return false;
  std::copy(a.begin(), a.end(), params);
  return true;
}

}  // namespace

Neighbours level_neighbours(const ModuleString& s, const std::array<bool, 256>& ignored) {
  const auto none = static_cast<std::uint32_t>(s.size());
  Neighbours n{std::vector<std::uint32_t>(s.size(), 0), std::vector<std::uint32_t>(s.size(), none)};
  // `last` is the nearest module to the left that a context reads: a '[' keeps it (a branch's first module
  // sees its parent), a ']' brings back the one before its '[' (the completed branch is skipped).
  std::vector<std::uint32_t> open, last_at_open;
  std::uint32_t last = none;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const std::uint8_t c = s.symbols[i];
    n.left[i] = last;
    if (c == '[') {
      open.push_back(static_cast<std::uint32_t>(i));
      last_at_open.push_back(last);
    } else if (c == ']') {
      if (!open.empty()) {
        n.partner[i] = open.back();
        n.partner[open.back()] = static_cast<std::uint32_t>(i);
        open.pop_back();
        last = last_at_open.back();
        last_at_open.pop_back();
      }
    } else if (!ignored[c]) {
      last = static_cast<std::uint32_t>(i);
    }
  }
  for (std::uint32_t i : open) n.partner[i] = none;
  return n;
}

bool left_context(const Production& p, const ModuleString& s, const Neighbours& n, std::size_t i, double* params) {
  std::size_t slot = 0;
  for (const Pattern& m : p.left) slot += m.params.size();
  std::size_t j = i;
  for (auto m = p.left.rbegin(); m != p.left.rend(); ++m) {
    j = n.left[j];
    if (j >= s.size()) return false;
    slot -= m->params.size();
    if (!binds(*m, s, j, params + slot)) return false;
  }
  return true;
}

bool right_context(const Production& p, const ModuleString& s, const Neighbours& n, std::size_t i,
                   const std::array<bool, 256>& ignored, double* params) {
  const std::vector<std::uint32_t>& partner = n.partner;
  std::size_t j = i;
  const std::size_t size = s.size();
  for (const Pattern& m : p.right) {
    if (m.symbol == ']') {
      int depth = 0;
      for (++j; j < size; ++j) {
        if (s.symbols[j] == '[') ++depth;
        if (s.symbols[j] == ']' && depth-- == 0) break;
      }
      if (j >= size) return false;
      continue;
    }
    while (true) {
      if (++j >= size) return false;
      const std::uint8_t c = s.symbols[j];
      if (c == '[' && m.symbol != '[') {
        j = partner[j];
        if (j >= size) return false;
      } else if (c == ']') {
        return false;
      } else if (!ignored[c]) {
        break;
      }
    }
    if (!binds(m, s, j, params)) return false;
    params += m.params.size();
  }
  return true;
}

}  // namespace selfsim::lsystem

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

std::vector<std::uint32_t> bracket_partners(const ModuleString& s) {
  std::vector<std::uint32_t> partner(s.size(), 0), open;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.symbols[i] == '[') open.push_back(static_cast<std::uint32_t>(i));
    if (s.symbols[i] == ']' && !open.empty()) {
      partner[i] = open.back();
      partner[open.back()] = static_cast<std::uint32_t>(i);
      open.pop_back();
    }
  }
  for (std::uint32_t i : open) partner[i] = static_cast<std::uint32_t>(s.size());
  return partner;
}

bool left_context(const Production& p, const ModuleString& s, const std::vector<std::uint32_t>& partner, std::size_t i,
                  const std::array<bool, 256>& ignored, double* params) {
  std::size_t slot = 0;
  for (const Pattern& m : p.left) slot += m.params.size();
  std::size_t j = i;
  for (auto m = p.left.rbegin(); m != p.left.rend(); ++m) {
    while (true) {
      if (j == 0) return false;
      --j;
      const std::uint8_t c = s.symbols[j];
      if (c == ']' && partner[j] < j)
        j = partner[j];
      else if (c != '[' && !ignored[c])
        break;
    }
    slot -= m->params.size();
    if (!binds(*m, s, j, params + slot)) return false;
  }
  return true;
}

bool right_context(const Production& p, const ModuleString& s, const std::vector<std::uint32_t>& partner, std::size_t i,
                   const std::array<bool, 256>& ignored, double* params) {
  std::size_t j = i;
  const std::size_t n = s.size();
  for (const Pattern& m : p.right) {
    if (m.symbol == ']') {
      int depth = 0;
      for (++j; j < n; ++j) {
        if (s.symbols[j] == '[') ++depth;
        if (s.symbols[j] == ']' && depth-- == 0) break;
      }
      if (j >= n) return false;
      continue;
    }
    while (true) {
      if (++j >= n) return false;
      const std::uint8_t c = s.symbols[j];
      if (c == '[' && m.symbol != '[') {
        j = partner[j];
        if (j >= n) return false;
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

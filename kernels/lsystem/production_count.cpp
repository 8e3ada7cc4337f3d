#include "kernels/lsystem/production_count.h"

#include <array>

namespace selfsim::lsystem {

namespace {

// The production matrix acts on per-symbol weights: after d rewriting steps, symbol s contributes
// w_d(s) = sum of w_{d-1}(t) over its replacement t, or w_0(s) if s has no rule.
template <class Weight>
std::array<double, 256> per_symbol(const Grammar& g, int depth, Weight weight) {
  std::array<double, 256> w{};
  for (int s = 0; s < 256; ++s) w[s] = weight(static_cast<char>(s));
  for (int d = 1; d <= depth; ++d) {
    std::array<double, 256> next = w;
    for (const auto& [symbol, replacement] : g.rules) {
      double total = 0;
      for (char t : replacement) total += w[static_cast<unsigned char>(t)];
      next[static_cast<unsigned char>(symbol)] = total;
    }
    w = next;
  }
  return w;
}

template <class Weight>
double count(const Grammar& g, int level, Weight weight) {
  const auto w = per_symbol(g, level, weight);
  double total = 0;
  for (char s : g.axiom) total += w[static_cast<unsigned char>(s)];
  return total;
}

}  // namespace

LevelCounts predict_counts(const Grammar& g, int level) {
  LevelCounts c;
  c.symbols = count(g, level, [](char) { return 1.0; });
  c.segments = count(g, level, [&](char s) { return g.draws(s) ? 1.0 : 0.0; });
  c.breaks = count(g, level, [&](char s) { return s == ']' || g.moves(s) ? 1.0 : 0.0; });
  return c;
}

std::array<double, 256> per_symbol_counts(const Grammar& g, int depth, Weight weight) {
  if (weight == Weight::Symbols) return per_symbol(g, depth, [](char) { return 1.0; });
  return per_symbol(g, depth, [&](char s) { return g.draws(s) ? 1.0 : 0.0; });
}

}  // namespace selfsim::lsystem

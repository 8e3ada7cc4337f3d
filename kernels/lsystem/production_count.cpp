#include "kernels/lsystem/production_count.h"

#include <algorithm>

namespace selfsim::lsystem {

namespace {

template <class Weight>
SymbolWeights weights_of(Weight weight) {
  SymbolWeights w{};
  for (int s = 0; s < 256; ++s) w[s] = weight(static_cast<char>(s));
  return w;
}

double total(const std::string& s, const SymbolWeights& w) {
  double t = 0;
  for (char c : s) t += w[static_cast<unsigned char>(c)];
  return t;
}

// The deepest nesting of '[' reached while reading s, given each symbol's net nesting change and the
// deepest nesting reached inside it (relative to where it starts).
double peak(const std::string& s, const SymbolWeights& net, const SymbolWeights& inner) {
  double depth = 0, deepest = 0;
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    deepest = std::max(deepest, depth + inner[u]);
    depth += net[u];
  }
  return deepest;
}

}  // namespace

// The production matrix acts on per-symbol weights: after d rewriting steps, symbol s contributes
// w_d(s) = sum of w_{d-1}(t) over its replacement t, or w_0(s) if s has no rule.
void rewrite_weights(const Grammar& g, SymbolWeights& w) {
  SymbolWeights next = w;
  for (const auto& [symbol, replacement] : g.rules) next[static_cast<unsigned char>(symbol)] = total(replacement, w);
  w = next;
}

SymbolWeights symbol_weights(const Grammar& g, Weight weight) {
  if (weight == Weight::Symbols) return weights_of([](char) { return 1.0; });
  return weights_of([&](char s) { return g.draws(s) ? 1.0 : 0.0; });
}

LevelCounts predict_counts(const Grammar& g, int level, Progress& progress) {
  SymbolWeights symbols = symbol_weights(g, Weight::Symbols), segments = symbol_weights(g, Weight::Segments);
  SymbolWeights breaks = weights_of([&](char s) { return s == ']' || g.moves(s) ? 1.0 : 0.0; });
  // Branch nesting: '[' opens one (and reaches depth 1 inside itself), ']' closes one.
  SymbolWeights net = weights_of([](char s) { return s == '[' ? 1.0 : s == ']' ? -1.0 : 0.0; });
  SymbolWeights inner = weights_of([](char s) { return s == '[' ? 1.0 : 0.0; });
  for (int d = 1; d <= level; ++d) {
    if (progress.cancelled()) throw Cancelled();
    rewrite_weights(g, symbols);
    rewrite_weights(g, segments);
    rewrite_weights(g, breaks);
    SymbolWeights next_inner = inner;
    for (const auto& [symbol, replacement] : g.rules)
      next_inner[static_cast<unsigned char>(symbol)] = peak(replacement, net, inner);
    inner = next_inner;
    rewrite_weights(g, net);
  }
  return {total(g.axiom, symbols), total(g.axiom, segments), total(g.axiom, breaks), peak(g.axiom, net, inner)};
}

}  // namespace selfsim::lsystem

#include "kernels/lsystem/turtle/plant.h"

#include <algorithm>
#include <string_view>

namespace selfsim::lsystem {

namespace {

// Whether the axiom or a successor writes a symbol that `wanted` accepts: a byte grammar's text, or a
// module grammar's modules (its interpretation rules, what is drawn, included).
template <class F>
bool writes(const Grammar& g, F wanted) {
  if (!g.modules())
    return std::any_of(g.axiom.begin(), g.axiom.end(), wanted) ||
           std::any_of(g.rules.begin(), g.rules.end(),
                       [&](const auto& r) { return std::any_of(r.second.begin(), r.second.end(), wanted); });
  auto in = [&](const std::vector<Call>& calls) {
    return std::any_of(calls.begin(), calls.end(), [&](const Call& c) { return wanted(static_cast<char>(c.symbol)); });
  };
  if (in(g.start)) return true;
  for (const auto* rules : {&g.productions, &g.decomposition, &g.interpretation})
    for (const Production& p : *rules)
      for (const Successor& o : p.options)
        if (in(o.modules)) return true;
  return false;
}

}  // namespace

bool writes_symbol(const Grammar& g, char symbol) {
  return writes(g, [symbol](char c) { return c == symbol; });
}

bool branches(const Grammar& g) {
  // '[' pushes unless the grammar makes it a step (compiled_grammar.cpp).
  return !g.draws('[') && !g.moves('[') && writes_symbol(g, '[');
}

bool draws_in_3d(const Grammar& g) {
  if (g.dimension != 0) return g.dimension == 3;
  if (g.tropism != Vec3{}) return true;
  if (!g.modules()) return false;  // the byte turtle is 2D (the binding makes 3D grammars module grammars)
  return writes(g, [&](char c) {
    return turns_3d.find(c) != std::string_view::npos && !g.draws(c) && !g.moves(c) && !g.angles.contains(c);
  });
}

bool is_plant(const Grammar& g) { return branches(g) || draws_in_3d(g); }

bool normalizes(const Grammar& g, const TurtleOptions& opt) { return opt.normalize.value_or(!is_plant(g)); }

double start_heading(const Grammar& g, const TurtleOptions& opt) {
  if (!g.start_angles.empty()) return g.start_angle(opt.level);
  return !normalizes(g, opt) && is_plant(g) ? 90 : 0;
}

}  // namespace selfsim::lsystem

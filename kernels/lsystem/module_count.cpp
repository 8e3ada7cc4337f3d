#include "kernels/lsystem/module_count.h"

#include <map>
#include <utility>
#include <vector>

#include "kernels/lsystem/production.h"

namespace selfsim::lsystem {

namespace {

struct Size {
  double modules = 0, steps = 0;
  bool operator==(const Size&) const = default;
};

using Sizes = std::vector<Size>;

// Which rule rewrites a module depends on its symbol and parameter count alone (no condition, context or
// choice): that pair is its shape, numbered here.
struct Shapes {
  std::map<std::pair<std::uint8_t, std::size_t>, std::size_t> id;
  std::vector<std::uint8_t> symbol;

  std::size_t of(std::uint8_t s, std::size_t arity) {
    const auto [it, added] = id.try_emplace({s, arity}, symbol.size());
    if (added) symbol.push_back(s);
    return it->second;
  }
  void add(const std::vector<Production>& rules) {
    for (const Production& p : rules) {
      of(p.pred.symbol, p.pred.params.size());
      for (const Call& c : p.options[0].modules) of(c.symbol, c.args.size());
    }
  }
};

// A rule set as shape -> the shapes of its successor; shapes no rule rewrites have none.
struct Table {
  std::vector<std::vector<std::size_t>> successor;
  std::vector<bool> rewrites;
  bool empty = true;

  Table(const std::vector<Production>& rules, Shapes& shapes)
      : successor(shapes.symbol.size()), rewrites(shapes.symbol.size(), false), empty(rules.empty()) {
    for (const Production& p : rules) {  // the first rule written for a shape is the one that applies
      const std::size_t s = shapes.of(p.pred.symbol, p.pred.params.size());
      if (rewrites[s]) continue;
      rewrites[s] = true;
      for (const Call& c : p.options[0].modules) successor[s].push_back(shapes.of(c.symbol, c.args.size()));
    }
  }

  Size total(std::size_t s, const Sizes& w) const {
    Size t;
    for (std::size_t c : successor[s]) {
      t.modules += w[c].modules;
      t.steps += w[c].steps;
    }
    return t;
  }
};

// Rules every module of a shape follows the same way. A cut '%' drops what follows it in its branch, which
// the counts cannot follow, except in an interpretation (where it reaches the turtle as a symbol).
bool fixed(const std::vector<Production>& rules, bool cuts) {
  for (const Production& p : rules) {
    if (p.context() || !p.condition.empty() || p.options.size() != 1) return false;
    if (cuts)
      for (const Call& c : p.options[0].modules)
        if (c.symbol == '%') return false;
  }
  return true;
}

// The size of every shape expanded by `rules` up to `depth` levels deep (decomposition, interpretation),
// each module left where it stops weighing `leaf`.
Sizes expand(const Table& rules, int depth, const Sizes& leaf, Progress& progress) {
  Sizes w = leaf;
  for (int d = 0; d < depth && !rules.empty; ++d) {
    if (progress.cancelled()) throw Cancelled();
    Sizes next = leaf;
    for (std::size_t s = 0; s < w.size(); ++s)
      if (rules.rewrites[s]) next[s] = rules.total(s, w);
    if (next == w) break;  // every expansion ends above this depth: deeper ones change nothing
    w = std::move(next);
  }
  return w;
}

}  // namespace

std::optional<ModuleCounts> predict_module_counts(const Grammar& g, int level, const std::array<bool, 256>& steps,
                                                  bool interpret, Progress& progress) {
  if (!fixed(g.productions, true) || !fixed(g.decomposition, true) || !fixed(g.interpretation, false))
    return std::nullopt;
  Shapes shapes;
  for (const Call& c : g.start) {
    if (c.symbol == '%') return std::nullopt;
    shapes.of(c.symbol, c.args.size());
  }
  for (const auto* rules : {&g.productions, &g.decomposition, &g.interpretation}) shapes.add(*rules);
  const Table produce(g.productions, shapes), decompose(g.decomposition, shapes),
      interpretation(g.interpretation, shapes);
  Sizes leaf(shapes.symbol.size());
  for (std::size_t s = 0; s < leaf.size(); ++s) leaf[s] = {1, steps[shapes.symbol[s]] ? 1.0 : 0.0};
  // at[s]: what a module of shape s on the level being derived becomes by the end (a module no production
  // rewrites stays itself to the last level, where it is interpreted).
  Sizes at = interpret ? expand(interpretation, g.max_depth, leaf, progress) : leaf;
  // written[s]: the same for a module as a step writes it, before its decomposition.
  Sizes written = expand(decompose, g.max_depth, at, progress);
  for (int k = 1; k <= level; ++k) {
    if (progress.cancelled()) throw Cancelled();
    Sizes next = at;
    for (std::size_t s = 0; s < at.size(); ++s)
      if (produce.rewrites[s]) next[s] = produce.total(s, written);
    at = std::move(next);
    written = expand(decompose, g.max_depth, at, progress);
  }
  ModuleCounts out;
  for (const Call& c : g.start) {
    const Size& s = written[shapes.of(c.symbol, c.args.size())];
    out.modules += s.modules;
    out.steps += s.steps;
  }
  return out;
}

}  // namespace selfsim::lsystem

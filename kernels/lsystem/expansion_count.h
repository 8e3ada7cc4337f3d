// The size of a decomposition or interpretation (module_rewrite.h), counted before any of it is written.
// Such rules apply recursively up to max_depth levels deep, so one module may become exponentially many
// (A -> F A A: 2^max_depth): each module's expansion is counted first, without writing it, and refused
// when over the budget, instead of being found over it by drawing up to it.
//
// Counting is memoised per (module, depth) (and lineage, for rules with choices), so A -> F A A costs
// max_depth steps to count however many modules it writes; rules whose parameters never repeat cost the
// modules they write, and the count stops as soon as it passes its caps. It polls for a stop as it goes.
// Internal to kernels/lsystem.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/lsystem/rule_index.h"
#include "kernels/lsystem/rule_scope.h"

namespace selfsim::lsystem {

struct ExpansionSize {
  double modules = 0;                // modules written (before a cut '%' drops any)
  double steps = 0;                  // those among them that step: each makes a point when drawn
  bool over = false;                 // counting stopped past a cap: the sizes are lower bounds
  const Production* rule = nullptr;  // the rule that expands the module (null: none matches)
};

class ExpansionCount {
 public:
  // `steps` marks the symbols that make a point. `rules` and `scope` must outlive the counter.
  ExpansionCount(const RuleIndex& rules, int max_depth, RuleScope& scope, const std::array<bool, 256>& steps,
                 Progress& progress);

  // Whether a module of this symbol may expand into more than `modules` modules, bounded from the rules
  // alone (whatever their conditions and parameters); if not, counting it costs more than it can save.
  bool may_exceed(std::uint8_t symbol, double modules) const { return bound_[symbol] > modules; }

  // The expansion of one module (written deriving `level`, for messages), counted until it passes
  // max_modules or max_steps. Binds the scope (as matching does). Throws what evaluating the rules throws.
  ExpansionSize count(std::uint8_t symbol, std::span<const double> args, std::uint64_t lineage, int level,
                      double max_modules, double max_steps);

 private:
  struct Size {
    double modules, steps;
  };
  Size visit(std::uint8_t symbol, std::span<const double> args, std::uint64_t lineage, int depth);
  Size leaf(std::uint8_t symbol) const { return {1, steps_[symbol] ? 1.0 : 0.0}; }

  const RuleIndex& rules_;
  int max_depth_;
  RuleScope& scope_;
  std::array<bool, 256> steps_;
  Progress& progress_;
  std::array<double, 256> bound_;            // see may_exceed
  bool by_lineage_ = false;                  // the rules choose, so an expansion depends on the module's lineage
  std::vector<std::vector<double>> values_;  // evaluated successor parameters, one list per depth
  std::unordered_map<std::string, Size> memo_;
  int level_ = 0;
  double max_modules_ = 0, max_steps_ = 0;
  std::size_t visits_ = 0, next_poll_ = 0;
};

}  // namespace selfsim::lsystem

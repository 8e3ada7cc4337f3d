// Rewriting of module grammars (parametric, conditional, stochastic, context-sensitive: production.h),
// apart from drawing. Context-free grammars are expanded depth-first straight into the sink, one evaluated
// successor per level on a stack, like the byte kernel (rewrite.h); context-sensitive ones need each level's
// neighbours, so levels below the last are held in memory and the last is streamed.
//
// Stochastic choice is a pure function of the seed and the module's lineage: a module's lineage is a hash
// of its parent's and of its place among the same symbols in the parent's successor (the axiom's modules
// have the seed as parent). So the result does not depend on evaluation order or threads, and changing
// one rule changes only the choices below the modules that rule writes.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/lsystem/grammar.h"
#include "kernels/lsystem/module_string.h"
#include "kernels/lsystem/stochastic_choice.h"

namespace selfsim::lsystem {

// Receives a level's modules in order.
class ModuleSink {
 public:
  virtual ~ModuleSink() = default;
  virtual void module(std::uint8_t symbol, std::span<const double> args) = 0;
  // A run of modules, in order: one call for many (a turtle then draws them without a call each). By
  // default one by one.
  virtual void modules(const ModuleRun& r) {
    for (std::size_t i = r.begin; i < r.end; ++i) module(r.symbols[i], r.args_of(i));
  }
};

struct ModuleLimits {
  double work = 1e12;   // modules read and written over all levels before refusing (BudgetError)
  double held = 2.7e8;  // modules a context-sensitive grammar may hold in memory at once
  // Drawing: the sink's point budget and the symbols that make a point each. An interpretation predicted
  // to make more points than the budget leaves is refused before any of it is drawn.
  std::optional<PointBudget> points;
  std::array<bool, 256> steps{};
};

// Derives level `level` of g (g.modules() must be true) and feeds it to sink; with `interpret`, each module
// through g's interpretation rules first (drawing). Decomposition rules rewrite every module a step (or
// the axiom) writes, recursively, up to g.max_depth levels deep; each module's decomposition and
// interpretation is counted before it is written (expansion_count.h), and refused when over `limits`.
// Throws Error naming the rule and level when a parameter or condition evaluates to a division by zero or
// a non-finite number; BudgetError past `limits`; Cancelled when progress says so.
void rewrite_modules(const Grammar& g, int level, ModuleSink& sink, const ModuleLimits& limits, Progress& progress,
                     bool interpret = false);

// The level as ABOP text, modules with their parameters ("F(1)[+(30)A(0.5)]"); refuses one longer than
// max_modules.
std::string module_string_text(const Grammar& g, int level, double max_modules, Progress& progress);

}  // namespace selfsim::lsystem

// The scope a module grammar's expressions are evaluated in (the grammar's constants, then the parameters a
// matched rule binds), and the steps of applying a rule that deriving a level (module_rewrite.cpp) and
// predicting a decomposition or interpretation (expansion_count.h) share, so both match, choose, evaluate
// and report errors alike. Internal to kernels/lsystem.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernels/lsystem/grammar.h"
#include "kernels/lsystem/rule_index.h"

namespace selfsim::lsystem {

// rule_parser.cpp's bound on the parameters a rule binds, and the binding's on a grammar's constants.
constexpr std::size_t max_scope = 48 + max_constants;

class RuleScope {
 public:
  explicit RuleScope(const Grammar& g);

  // Where a matched rule's parameters are bound, after the constants.
  double* params() { return scope_.data() + k_; }
  std::span<const double> constants() const { return {scope_.data(), k_}; }
  bool stochastic() const { return stochastic_; }

  // The first production of `index` that rewrites a module given by its symbol and parameters, ignoring
  // context (decomposition, interpretation, context-free grammars), its parameters bound; null if none.
  // `level` names the level being derived in messages.
  const Production* match(const RuleIndex& index, std::uint8_t symbol, std::span<const double> args, int level);
  // Whether p's condition holds for the parameters bound of a module with `args`. Throws Error naming the
  // rule, the level and the module when the condition cannot be computed (a division by zero, a NaN).
  bool holds(const Production& p, std::span<const double> args, int level) const;
  // The successor p chooses for a module of this lineage (its parameters bound).
  const Successor& chosen(const Production& p, std::uint64_t lineage) const;
  // A written module's lineage: hashed only when a choice will read it.
  std::uint64_t child(std::uint64_t parent, const Call& c) const;
  // Evaluates the successor's parameters into `values` (the modules' parameters, in order), before any of
  // them is written: writing may match again, which binds the scope again.
  void evaluate_successor(const Production& p, const Successor& succ, int level, std::vector<double>& values) const;
  // Parameter k of module c, written by p (null: the axiom) deriving `level`; throws Error naming them.
  double evaluate(const Expression& e, std::span<const double> scope, const Call& c, std::size_t k, const Production* p,
                  int level) const;

 private:
  std::array<double, max_scope> scope_{};  // the grammar's constants, then the parameters a rule binds
  std::size_t k_ = 0;                      // how many constants
  bool stochastic_;
};

}  // namespace selfsim::lsystem

#include "kernels/lsystem/rule_scope.h"

#include <algorithm>
#include <string>

#include "kernels/base/error.h"
#include "kernels/lsystem/module_string.h"
#include "kernels/lsystem/stochastic_choice.h"

namespace selfsim::lsystem {

namespace {

std::string rule_text(const Production& p, int level) {
  return p.where + " (" + p.text + ") deriving level " + std::to_string(level);
}

}  // namespace

RuleScope::RuleScope(const Grammar& g) : stochastic_(g.stochastic()) {
  if (g.constants.size() > max_constants) throw Error("internal error: too many constants");
  for (const auto& [name, value] : g.constants) scope_[k_++] = value;
}

const Production* RuleScope::match(const RuleIndex& index, std::uint8_t symbol, std::span<const double> args,
                                   int level) {
  for (const Production* p : index.by_symbol[symbol]) {
    if (p->pred.params.size() != args.size()) continue;
    std::copy(args.begin(), args.end(), params());
    if (holds(*p, args, level)) return p;
  }
  return nullptr;
}

bool RuleScope::holds(const Production& p, std::span<const double> args, int level) const {
  if (p.condition.empty()) return true;
  try {
    return p.condition.eval({scope_.data(), k_ + static_cast<std::size_t>(p.slots)}) != 0;
  } catch (const EvalError& err) {
    throw Error(rule_text(p, level) + ": its condition for " + module_text(p.pred.symbol, args) + ": " + err.what());
  }
}

const Successor& RuleScope::chosen(const Production& p, std::uint64_t lineage) const {
  if (p.options.size() == 1) return p.options[0];
  return p.options[choose_option(p.options, choice_point(lineage))];
}

std::uint64_t RuleScope::child(std::uint64_t parent, const Call& c) const {
  return stochastic_ ? child_lineage(parent, c.salt) : 0;
}

void RuleScope::evaluate_successor(const Production& p, const Successor& succ, int level,
                                   std::vector<double>& values) const {
  const std::span<const double> bound{scope_.data(), k_ + static_cast<std::size_t>(p.slots)};
  values.clear();
  for (const Call& c : succ.modules)
    for (std::size_t k = 0; k < c.args.size(); ++k) values.push_back(evaluate(c.args[k], bound, c, k, &p, level));
}

double RuleScope::evaluate(const Expression& e, std::span<const double> scope, const Call& c, std::size_t k,
                           const Production* p, int level) const {
  try {
    return e.eval(scope);
  } catch (const EvalError& err) {
    const std::string where = p == nullptr ? "option 'axiom'" : rule_text(*p, level);
    throw Error(where + ": parameter " + std::to_string(k + 1) + " of " + module_text(c.symbol, {}) + ": " +
                err.what());
  }
}

}  // namespace selfsim::lsystem

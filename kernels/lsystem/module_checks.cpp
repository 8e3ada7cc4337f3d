#include "kernels/lsystem/module_checks.h"

#include <array>
#include <set>

#include "kernels/base/error.h"

namespace selfsim::lsystem {

namespace {

std::string shown(std::uint8_t s) { return std::string(1, static_cast<char>(s)); }

std::string parameters(std::size_t n) { return std::to_string(n) + (n == 1 ? " parameter" : " parameters"); }

// Calls f(call, where) for the axiom's modules and every successor's.
// Calls f(call, rule) for the axiom's modules (rule null) and every successor's.
template <class F>
void each_written(const Grammar& g, F&& f) {
  for (const Call& c : g.start) f(c, static_cast<const Production*>(nullptr));
  for (const auto* rules : {&g.productions, &g.decomposition, &g.interpretation})
    for (const Production& p : *rules)
      for (const Successor& o : p.options)
        for (const Call& c : o.modules) f(c, &p);
}

std::string rule_name(const Production* p) { return p == nullptr ? "option 'axiom'" : p->where + " (" + p->text + ")"; }

}  // namespace

void check_arities(const Grammar& g) {
  std::array<std::set<std::size_t>, 256> taken;
  std::array<const Production*, 256> first{};
  for (const auto* rules : {&g.productions, &g.decomposition, &g.interpretation})
    for (const Production& p : *rules) {
      taken[p.pred.symbol].insert(p.pred.params.size());
      if (first[p.pred.symbol] == nullptr) first[p.pred.symbol] = &p;
    }
  each_written(g, [&](const Call& c, const Production* rule) {
    const std::set<std::size_t>& t = taken[c.symbol];
    if (t.empty() || t.count(c.args.size()) > 0) return;
    throw Error("arity mismatch: " + rule_name(rule) + " writes " + shown(c.symbol) + " with " +
                parameters(c.args.size()) + ", but " + first[c.symbol]->where + " (" + first[c.symbol]->text +
                ") takes " + parameters(*t.begin()));
  });
}

std::vector<std::string> context_warnings(const Grammar& g) {
  std::array<bool, 256> written{};
  each_written(g, [&](const Call& c, const Production*) { written[c.symbol] = true; });
  std::vector<std::string> out;
  for (const Production& p : g.productions)
    for (const auto* side : {&p.left, &p.right})
      for (const Pattern& m : *side) {
        if (m.symbol == '[' || m.symbol == ']') continue;
        const std::string where = p.where + " (" + p.text + "): its context '" + shown(m.symbol) + "'";
        if (!written[m.symbol])
          out.push_back(where + " is written by neither the axiom nor any successor, so the rule never applies");
        else if (g.ignore.find(static_cast<char>(m.symbol)) != std::string::npos)
          out.push_back(where +
                        " is in the ignore list (option 'ignore'), which context matching skips, so the "
                        "rule never applies");
      }
  return out;
}

}  // namespace selfsim::lsystem

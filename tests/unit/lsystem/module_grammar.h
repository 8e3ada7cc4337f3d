// A module grammar from an axiom and ABOP rule strings, for the module engine's tests.
#pragma once

#include <string>
#include <vector>

#include "kernels/lsystem/grammar.h"
#include "kernels/lsystem/rule_parser.h"

namespace test {

inline selfsim::lsystem::Grammar module_grammar(const std::string& axiom, const std::vector<std::string>& rules) {
  selfsim::lsystem::Grammar g;
  g.axiom = axiom;
  g.start = selfsim::lsystem::parse_calls(axiom, {});
  for (const std::string& r : rules)
    g.productions.push_back(selfsim::lsystem::parse_rule(r, "rule " + std::to_string(g.productions.size() + 1)));
  return g;
}

}  // namespace test

// A module grammar from an axiom and ABOP rule strings, and rules alone, for the module engine's tests.
#pragma once

#include <array>
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

// Rule entries parsed as the bindings parse them ("entry N" naming each).
inline std::vector<selfsim::lsystem::Production> rules_of(const std::vector<std::string>& texts) {
  std::vector<selfsim::lsystem::Production> out;
  for (const std::string& t : texts)
    out.push_back(selfsim::lsystem::parse_rule(t, "entry " + std::to_string(out.size() + 1)));
  return out;
}

// The drawing symbols of a grammar where only F draws.
inline std::array<bool, 256> draws_f() {
  std::array<bool, 256> steps{};
  steps['F'] = true;
  return steps;
}

}  // namespace test

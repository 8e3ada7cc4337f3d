#include "kernels/lsystem/grammar.h"

#include <cmath>
#include <cstdio>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/lsystem/module_checks.h"

namespace selfsim::lsystem {

namespace {

std::string shown(char c) {
  if (c >= 33 && c < 127) return std::string(1, c);
  return "\\" + std::to_string(static_cast<unsigned char>(c));
}

// A ']' before its '[' would pop an empty turtle stack, and a '[' never closed leaves a branch open to
// the end (every level expands each string in one piece): both are mistakes, as in a module grammar's
// axiom and successors (rule_parser.cpp).
void require_balanced(const std::string& s, const std::string& what) {
  int depth = 0;
  for (char c : s) {
    depth += c == '[' ? 1 : c == ']' ? -1 : 0;
    if (depth < 0) throw Error(what + " has a ']' without a matching '['");
  }
  if (depth > 0) throw Error(what + " has a '[' that is never closed (a ']' is missing)");
}

}  // namespace

void Grammar::validate() const {
  if (axiom.empty()) throw Error("option 'axiom' must be a non-empty string");
  require_balanced(axiom, "option 'axiom'");
  for (const auto& [symbol, replacement] : rules) {
    if (symbol == '[' || symbol == ']')
      throw Error("option 'rules': the branch symbol '" + shown(symbol) + "' cannot have a rule");
    require_balanced(replacement, "option 'rules': the rule for '" + shown(symbol) + "'");
  }
  check_finite(angle, "option 'angle'");
  for (const auto& [symbol, degrees] : angles) check_finite(degrees, "option 'angles['" + shown(symbol) + "']'");
  for (double a : start_angles) check_finite(a, "option 'start_angle'");
  check_finite(shrink, "option 'shrink'");
  if (!(shrink > 0)) throw Error("option 'shrink' must be a positive number, got " + number_text(shrink));
  for (char c : draw)
    if (moves(c)) throw Error("option 'draw': symbol '" + shown(c) + "' is also in 'move'");
  for (const auto& [option, symbols] : {std::pair{"draw", &draw}, std::pair{"move", &move}})
    for (char c : *symbols)
      if (c == '[' || c == ']')
        throw Error(std::string("option '") + option + "': '" + shown(c) +
                    "' is a branch symbol (save and restore the turtle) and cannot also step");
  // Bounds the work of predicting a level (levels x grammar size) before any Progress check can run.
  double size = static_cast<double>(axiom.size());
  for (const auto& [symbol, replacement] : rules) size += static_cast<double>(replacement.size());
  check_range(max_depth, 0, max_rule_depth, "option 'max_depth'");
  for (const auto* rules : {&decomposition, &interpretation})
    for (const Production& p : *rules)
      if (p.context())
        throw Error(p.where + " (" + p.text + "): decomposition and interpretation rules take no context");
  for (const auto* rules : {&productions, &decomposition, &interpretation})
    for (const Production& p : *rules) {
      double total = 0;
      for (const Successor& o : p.options) {
        if (!(o.weight >= 0) || !std::isfinite(o.weight))
          throw Error(p.where + ": a stochastic weight must be a finite number >= 0, got " + number_text(o.weight));
        total += o.weight;
        size += static_cast<double>(o.modules.size());
      }
      if (!(total > 0)) throw Error(p.where + ": the stochastic weights are all zero (one must be positive)");
    }
  if (modules()) check_arities(*this);
  if (size > max_grammar_symbols)
    throw Error("the axiom and rules hold " + std::to_string(static_cast<long long>(size)) +
                " symbols, over the limit of " + std::to_string(static_cast<long long>(max_grammar_symbols)));
}

bool Grammar::stochastic() const {
  for (const auto* rules : {&productions, &decomposition, &interpretation})
    for (const Production& p : *rules)
      if (p.options.size() > 1) return true;
  return false;
}

double Grammar::turn_of(char c) const {
  if (auto it = angles.find(c); it != angles.end()) return it->second;
  switch (c) {
    case '+':
      return angle;
    case '-':
      return -angle;
    case '|':
      return 180;
    default:
      return 0;
  }
}

}  // namespace selfsim::lsystem

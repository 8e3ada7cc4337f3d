// The rules of an L-system beyond plain symbol replacement (ABOP chapters 1.5-1.10): parametric modules
// A(x, y), conditions, left and right contexts, and stochastic choice among weighted successors. Plain
// grammars (every rule one fixed string of single symbols) never use these: they keep the streaming byte
// kernel (rewrite.h), and Grammar::productions stays empty for them.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "kernels/lsystem/expression.h"

namespace selfsim::lsystem {

// A module as a rule's left side matches it: a symbol and the names its parameters bind.
struct Pattern {
  std::uint8_t symbol = 0;
  std::vector<std::string> params;
};

// A module as a successor writes it: a symbol and one compiled expression per parameter.
struct Call {
  std::uint8_t symbol = 0;
  std::vector<Expression> args;
  std::uint64_t salt = 0;  // the symbol and how many of it come before in the same text: lineage (module_rewrite.h)
};

// One weighted choice of a production.
struct Successor {
  double weight = 1;
  std::vector<Call> modules;
  // The modules' symbols and where each one's parameters end among all of theirs (ModuleString's layout),
  // so the last level goes to the turtle without being copied module by module.
  std::vector<std::uint8_t> symbols;
  std::vector<std::uint32_t> arg_end;

  void set_modules(std::vector<Call> calls) {
    modules = std::move(calls);
    symbols.clear();
    arg_end.clear();
    std::uint32_t n = 0;
    for (const Call& c : modules) {
      symbols.push_back(c.symbol);
      arg_end.push_back(n += static_cast<std::uint32_t>(c.args.size()));
    }
  }
};

// left < pred > right : condition -> successors. Names in scope, in slot order: the grammar's constants
// (Grammar::constants), the left context's parameters, the predecessor's, then the right context's.
struct Production {
  std::vector<Pattern> left;  // nearest module last; no branches
  Pattern pred;
  std::vector<Pattern> right;  // may hold '[' and ']' (a right context may enter branches)
  Expression condition;        // empty: always
  std::vector<Successor> options;
  std::string text;   // as written, for messages
  std::string where;  // "rule 3", "option 'rules' line 4", "rule for 'F'": names it in messages
  int slots = 0;      // parameters the rule binds (after the grammar's constants)

  bool context() const { return !left.empty() || !right.empty(); }
};

}  // namespace selfsim::lsystem

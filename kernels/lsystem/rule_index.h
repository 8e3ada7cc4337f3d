// The productions of a grammar indexed by predecessor symbol, in the order they are tried
// (module_rewrite.cpp). Internal to kernels/lsystem.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernels/lsystem/production.h"

namespace selfsim::lsystem {

// The productions that may rewrite each symbol, in the order they are tried: those with a context first,
// then the others, each group in the order written.
struct RuleIndex {
  std::array<std::vector<const Production*>, 256> by_symbol;
  bool context = false;

  std::size_t total = 0;  // productions indexed

  bool empty_for(std::uint8_t s) const { return by_symbol[s].empty(); }

  explicit RuleIndex(const std::vector<Production>& rules) {
    for (bool with_context : {true, false})
      for (const Production& p : rules)
        if (p.context() == with_context) {
          by_symbol[p.pred.symbol].push_back(&p);
          ++total;
          context = context || with_context;
        }
  }
};

}  // namespace selfsim::lsystem

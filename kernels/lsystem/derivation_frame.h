// One frame of module_rewrite.cpp's depth-first derivation of a context-free grammar: the successor a level
// wrote for one module, read in place from its production, or held when decomposition rewrote it.
#pragma once

#include <cstdint>
#include <vector>

#include "kernels/lsystem/module_string.h"
#include "kernels/lsystem/production.h"
#include "kernels/lsystem/stochastic_choice.h"

namespace selfsim::lsystem {

// A level's successor on the depth-first stack: read in place from its production (the symbols and
// layout the Successor keeps, the parameters as evaluated), or held when decomposition rewrote it.
struct DerivationFrame {
  ModuleString held;
  std::vector<double> values;
  const Successor* succ = nullptr;  // null: held
  std::uint64_t parent = 0;         // the rewritten module's lineage (stochastic grammars)
  ModuleRun run{};

  void hold() {
    succ = nullptr;
    run = run_of(held, 0, held.size());
  }
  void view(const Successor& s, std::uint64_t lineage) {
    succ = &s;
    parent = lineage;
    run = {s.symbols.data(), s.arg_end.data(), values.data(), 0, s.symbols.size()};
  }
  std::uint64_t lineage(std::size_t i, bool stochastic) const {
    if (!stochastic) return 0;
    return succ == nullptr ? held.lineage[i] : child_lineage(parent, succ->modules[i].salt);
  }
};

}  // namespace selfsim::lsystem

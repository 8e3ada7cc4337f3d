// Sizes of a module grammar's level predicted from its rules before anything is derived, as
// production_count.h predicts a plain grammar's, with decomposition and interpretation folded in: when no
// rule has a condition, a context or a choice (and no cut '%' drops modules), which rule rewrites a module
// depends only on its symbol and how many parameters it has, so each such shape's size after d more steps
// follows from the sizes one step less deep (a production matrix over shapes). Grammars with conditions,
// contexts or choices cannot be predicted: they are counted as they are derived (module_rewrite.h).
// Internal to kernels/lsystem.
#pragma once

#include <array>
#include <optional>

#include "kernels/base/progress.h"
#include "kernels/lsystem/grammar.h"

namespace selfsim::lsystem {

struct ModuleCounts {
  double modules = 0;  // modules the level feeds to the sink (through interpretation when interpreting)
  double steps = 0;    // those among them whose symbol is marked in `steps`
};

// The counts of module grammar g at `level`, or nothing when its rules cannot be predicted. Costs
// level x max_depth x grammar size; polls for a stop at every level and depth.
std::optional<ModuleCounts> predict_module_counts(const Grammar& g, int level, const std::array<bool, 256>& steps,
                                                  bool interpret, Progress& progress);

}  // namespace selfsim::lsystem

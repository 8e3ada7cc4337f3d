// rewrite_modules() on a thread of its own, feeding the caller's sink in batches: the derivation and the
// turtle run at the same time on two cores. The sink sees exactly the modules, in exactly the order,
// that rewrite_modules() would give it directly, so the result is the same bytes; only the time differs.
#pragma once

#include "kernels/base/progress.h"
#include "kernels/lsystem/grammar.h"
#include "kernels/lsystem/module_rewrite.h"

namespace selfsim::lsystem {

// As rewrite_modules(); the sink is called on the calling thread only. Errors from either side are
// rethrown here (the derivation's first); a failing sink stops the derivation.
void rewrite_modules_piped(const Grammar& g, int level, ModuleSink& sink, const ModuleLimits& limits,
                           Progress& progress, bool interpret);

}  // namespace selfsim::lsystem

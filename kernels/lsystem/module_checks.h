// Checks of a module grammar that look at all its rules together, before any rewriting.
#pragma once

#include <string>
#include <vector>

#include "kernels/lsystem/grammar.h"

namespace selfsim::lsystem {

// Throws Error when a module is written with a number of parameters that no rule for its symbol takes
// (ABOP: such a module would silently never be rewritten), naming where it is written.
void check_arities(const Grammar& g);
// One line per context that can never match: a context symbol that neither the axiom nor any successor
// writes, or one the ignore list skips.
std::vector<std::string> context_warnings(const Grammar& g);

}  // namespace selfsim::lsystem

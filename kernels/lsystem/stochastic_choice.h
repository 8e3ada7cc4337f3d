// Stochastic choice by lineage (module_rewrite.h): a module's choice is a pure function of the seed and
// where the module came from, never of the order of evaluation or the thread.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "kernels/lsystem/production.h"

namespace selfsim::lsystem {

// The lineage every axiom module's descends from.
std::uint64_t root_lineage(std::uint64_t seed);
// A child module's lineage from its parent's and its salt (symbol and ordinal in the successor).
std::uint64_t child_lineage(std::uint64_t parent, std::uint64_t salt);
// The point in [0, 1) a module of this lineage chooses at.
inline double choice_point(std::uint64_t lineage) { return static_cast<double>(lineage >> 11) * 0x1.0p-53; }
// The option that the choice u in [0, 1) picks, in proportion to the weights (not all zero).
std::size_t choose_option(std::span<const Successor> options, double u);

}  // namespace selfsim::lsystem

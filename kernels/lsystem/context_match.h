// Branch-aware context matching (ABOP 1.8) over a level held in memory, for module_rewrite.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "kernels/lsystem/module_string.h"
#include "kernels/lsystem/production.h"

namespace selfsim::lsystem {

// What context matching needs to know of a level, found in one pass.
struct Neighbours {
  std::vector<std::uint32_t> partner;  // each bracket's partner (s.size() for a '[' never closed; others 0)
  std::vector<std::uint32_t> left;     // each module's left neighbour (or none: s.size()); see left_context
};
Neighbours level_neighbours(const ModuleString& s, const std::array<bool, 256>& ignored);

// Whether p's left context matches before module i of s, binding its parameters at `params` (in slot
// order). It is read leftwards: completed branches and the '[' opening the module's own branch are
// skipped, as are ignored symbols (so each module's left neighbour is known in advance, and a match costs
// the context's length, however many branches lie between).
bool left_context(const Production& p, const ModuleString& s, const Neighbours& n, std::size_t i, double* params);
// Whether p's right context matches after module i, binding its parameters at `params`. A '[' in it
// enters a branch, a ']' skips the rest of the branch entered; branches it does not enter are skipped,
// ignored symbols too, and the end of the module's own branch ends it.
bool right_context(const Production& p, const ModuleString& s, const Neighbours& n, std::size_t i,
                   const std::array<bool, 256>& ignored, double* params);

}  // namespace selfsim::lsystem

// Branch-aware context matching (ABOP 1.8) over a level held in memory, for module_rewrite.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "kernels/lsystem/module_string.h"
#include "kernels/lsystem/production.h"

namespace selfsim::lsystem {

// For each bracket of s, the position of its partner (s.size() for a '[' never closed; other modules: 0).
std::vector<std::uint32_t> bracket_partners(const ModuleString& s);

// Whether p's left context matches before module i of s, binding its parameters at `params` (in slot
// order). It is read leftwards: completed branches and the '[' opening the module's own branch are
// skipped, as are ignored symbols.
bool left_context(const Production& p, const ModuleString& s, const std::vector<std::uint32_t>& partner, std::size_t i,
                  const std::array<bool, 256>& ignored, double* params);
// Whether p's right context matches after module i, binding its parameters at `params`. A '[' in it
// enters a branch, a ']' skips the rest of the branch entered; branches it does not enter are skipped,
// ignored symbols too, and the end of the module's own branch ends it.
bool right_context(const Production& p, const ModuleString& s, const std::vector<std::uint32_t>& partner, std::size_t i,
                   const std::array<bool, 256>& ignored, double* params);

}  // namespace selfsim::lsystem

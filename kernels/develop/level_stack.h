// Developing fractal curves (seed 002 §2): the levels of a curve's construction stacked in 3D, level l at
// height z_l, with the self-similar rule of §2: the gap between levels l and l+1 is `height` times the
// segment length of level l (the mean, for curves whose segments differ), so the stack is as self-similar as
// the curves (dragon gaps shrink by 1/√2 a level, terdragon gaps by 1/√3). Level 0 is on top: z_0 = 0 and the
// finer levels lie below, as the paper's sculptures stand.
#pragma once

#include <span>
#include <vector>

#include "kernels/geom/polyline.h"

namespace selfsim::develop {

// Heights z_0 = 0 > z_1 > ... of the levels. Each level must be one path with at least one segment.
std::vector<double> level_heights(std::span<const Polyline* const> levels, double height);

// How consecutive levels refine each other segment by segment: every segment of level l is replaced by b
// consecutive segments of level l+1 with the same ends (point b·j of level l+1 is point j of level l, to a
// billionth of the curve's size), the same b for every level. Returns b; throws Error naming the first level
// and point where that fails (Hilbert levels do not refine this way; the dragon, terdragon, arrowhead, Koch
// and Gosper levels do).
int refinement_branching(std::span<const Polyline* const> levels);

// True when every level is a closed loop (back at its start): the stack is then an annulus, not a disk.
bool closed_levels(std::span<const Polyline* const> levels);

// Throws Error naming the first thing that keeps a stack from developing: fewer than two levels, a level
// that is not one path, has no segment, a non-finite point or a zero-length segment, open levels mixed with
// closed ones, a closed level of fewer than 3 segments. Returns whether the levels are closed.
bool check_stack(std::span<const Polyline* const> levels);

}  // namespace selfsim::develop

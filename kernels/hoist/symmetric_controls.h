// The editing constraints of seed 000 §3.2: base curves that are bilaterally or rotationally symmetric,
// built from the first half of their control points, so the resulting self-similar curve is symmetric too.
#pragma once

#include <vector>

#include "kernels/geom/vec2.h"

namespace selfsim::hoist {

// half, then its mirror images in the line x = 1/2 ((x, y) -> (1 − x, y)) in reverse order: a control list
// symmetric left to right. half starts at (0,0); a last point on x = 1/2 is the middle one, not repeated.
// Throws Error for fewer than 2 points or a start other than (0,0).
std::vector<Vec2> mirror_controls(const std::vector<Vec2>& half);

// half, then its images under the half-turn about (1/2, 0) ((x, y) -> (1 − x, −y)) in reverse order: a
// control list symmetric under that turn. A last point at (1/2, 0) is the middle one, not repeated.
std::vector<Vec2> rotate_controls(const std::vector<Vec2>& half);

}  // namespace selfsim::hoist

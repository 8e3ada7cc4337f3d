// What `exclusion.curve` requires of its start curves, checked before any work: each has a segment, finite
// points inside the region, no zero-length segment, touches the region's boundary at most at its own two
// ends (Figure 3 runs corner to corner), and no two segments of the start curves meet unless they follow
// each other along one curve. Each failure is an Error naming the curve, the point or segment, and why.
#pragma once

#include <span>

#include "kernels/geom/polyline.h"
#include "kernels/region/region.h"

namespace selfsim::exclusion {

// A start path that ends exactly where it starts (at least three segments) is a closed curve: starts are
// given, not walked, so the exact test (unlike selfsim::closed_path) is the right one.
bool exact_loop(std::span<const Vec2> p);

// `shown`: the same start in the caller's coordinates, for messages (the checks run on `start`).
void check_start(const Region& region, const Polyline& start, const Polyline& shown);

}  // namespace selfsim::exclusion

// The exclusion curve as it was after level k: its points of level ≤ k. A point, once placed, never moves
// (exclusion_curve.h), so these are exactly the points and segments level k made, with their fields; no
// re-run is needed for a picture or a dimension estimate of one level.
#pragma once

#include "kernels/base/progress.h"
#include "kernels/geom/polyline.h"

namespace selfsim::exclusion {

// Throws Error when the curve has no integer point field `level`.
Polyline curve_at_level(const Polyline& curve, int k, Progress& progress);

}  // namespace selfsim::exclusion

// Fewer points within a tolerance: seed 000 §3.2 rebuilt its final curves with a smaller number of points in
// an illustration program; selfsim does it itself with the Ramer–Douglas–Peucker rule: a path keeps its ends,
// and a run of points between two kept ones is replaced by the chord when every point of the run lies within
// `tolerance` of it, otherwise the farthest point is kept (the middle one where that lies near an end of the
// run: O(n log n) work whatever the curve) and both halves are looked at again.
#pragma once

#include "kernels/base/progress.h"
#include "kernels/geom/polyline.h"

namespace selfsim::hoist {

// Every path of c simplified; the kept points keep their point fields, paths their cell fields. Every
// removed point lies within `tolerance` (> 0, in the curve's units) of the simplified path. A closed path
// stays closed.
Polyline simplify(const Polyline& c, double tolerance, Progress& progress);

}  // namespace selfsim::hoist

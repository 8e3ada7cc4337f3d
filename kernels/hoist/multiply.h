// MULTIPLY of seed 000 §2.2: m consecutive copies of a curve C running from (0,0) to (1,0), copy i laid over
// [i, i+1] under its transform (kernels/geom/segment_transform.h), the whole scaled by 1/m so it runs from
// (0,0) to (1,0) again. A non-integer m ends with an initial part of a copy (the fraction m − ⌊m⌋ of its
// arclength, as walked); the result is then scaled and turned so it still ends at (1,0) (§2.2, last paragraph).
#pragma once

#include <vector>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/polyline.h"
#include "kernels/geom/segment_transform.h"

namespace selfsim::hoist {

struct MultiplyOptions {
  double multiplicity = 2;                   // m, in [1, 1e6]; 1 returns C
  std::vector<SegmentTransform> transforms;  // copy i takes transforms[i mod size]; empty for all Identity
  PointBudget budget;                        // refuse (before any work) results predicted not to fit

  void validate() const;
};

// The number of copies (⌈m⌉, a last partial copy counted).
double copies(double multiplicity);
// The points the result will have: exactly for whole m; for a non-integer m about that many (the partial
// copy's share depends on where C's points lie along it). multiply() checks its exact count against the
// budget before allocating.
double multiplied_points(std::size_t c_points, double multiplicity);

// C multiplied: one path. Point field `t` (where along the limit curve a point lies, in [0, 1]) is C's own
// `t` (or C's arclength fraction) carried into copy i as (i + t)/m, or (i + 1 − t)/m for a copy walked
// backwards; C's uniform point fields are kept; other point fields, which copies would make wrong (a
// tangent, an arclength), are dropped. Throws Error if C is not one path from (0,0) to (1,0).
Polyline multiply(const Polyline& c, const MultiplyOptions& opt, Progress& progress);

}  // namespace selfsim::hoist

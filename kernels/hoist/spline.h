// Smooth base curves for hoisting (seed 000 §3.1): uniform cubic B-splines (approximating their control
// points, C2) and Catmull-Rom splines (interpolating them, C1), sampled adaptively into a polyline that
// records a unit tangent at every sample.
//
// Both run from the first control point to the last: the list is extended at each end by a phantom point
// (2·P0 − P1 before, 2·Pn − Pn−1 after), which makes a uniform B-spline start exactly at P0 with tangent
// P1 − P0 (and Catmull-Rom too), so the curve is pinned where seed 000 §3.2 pins it.
#pragma once

#include <vector>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/polyline.h"

namespace selfsim::hoist {

enum class SplineKind { BSpline, CatmullRom };

struct SplineOptions {
  SplineKind kind = SplineKind::BSpline;
  std::vector<Vec2> points;  // control points, at least 3; the first (0,0) and the last (1,0)
  double flatness = 1e-4;    // largest distance of the curve from a sample chord, in units of the (0,0)–(1,0) span
  bool normalize = false;    // map the control points by the similarity taking the first to (0,0), the last to (1,0)
  PointBudget budget;        // refuse (while sampling) more samples than fit

  // Throws Error naming the first bad field: too few points, unpinned ends (without normalize), coinciding
  // ends, non-finite points, a flatness outside [1e-9, 0.1].
  void validate() const;
};

// The adaptive sampling: each span is split in half while the curve at the middle of a piece lies farther
// than `flatness` from the piece's chord (and at least twice, so an S-shaped span is never mistaken for a
// straight one), down to 2^16 pieces a span. One path from (0,0) to (1,0); point fields `tangent` (2
// components, the unit tangent) and `t` (the fraction of arclength at the sample).
Polyline sample_spline(const SplineOptions& opt, Progress& progress);

}  // namespace selfsim::hoist
